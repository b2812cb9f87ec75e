#pragma once
// The stage function of a mechanical system (DESIGN.md): at one integrator stage, every force
// provider of the one list adds its forces, then the set-point forces (joint servos along their
// ramps, actor loads), then the kernel computes the accelerations (ABA, hybrid dynamics for
// prescribed joints, or the loop-constrained dynamics). Allocation-free.
#include <Eigen/Core>

#include "dynamics/data.hpp"
#include "dynamics/external_forces.hpp"
#include "mechanics/data.hpp"
#include "mechanics/set_points.hpp"
#include "mechanics/system.hpp"

namespace yardsim::mechanics {

// (system, set-points) => d.prescribedMask flags the dofs whose motion is prescribed; true when any
bool prescribedDofs(const System& s, Data& d, const SetPoints& sp);

// (t, q, v, kinematics of (q, v) in kin, set-points) => the servos' joint forces added to tau
// (N m or N: ramp reference, PD at the servo bandwidth, bias-force feedforward, bounded) and the
// actors' loads added to f (world frame)
void setPointForces(const System& s, Data& d, const SetPoints& sp, double t,
                    const Eigen::VectorXd& q, const Eigen::VectorXd& v, const dynamics::Data& kin,
                    dynamics::ExternalForces& f, Eigen::VectorXd& tau);

// (t, q, v, kinematics of (q, v) in kin, the set-points d.setPoints) => every provider's forces,
// then the set-point forces, added to f and tau; the prescribed dofs handed to the kernel
void stageForces(const System& s, Data& d, double t, const Eigen::VectorXd& q,
                 const Eigen::VectorXd& v, const dynamics::Data& kin, dynamics::ExternalForces& f,
                 Eigen::VectorXd& tau);

// (system, workspace) => d.kernel evaluates stageForces at every stage, and reports the regime of
// the providers whose law switches (a contact) when the system has one
void connectStage(const System& s, Data& d);

}  // namespace yardsim::mechanics
