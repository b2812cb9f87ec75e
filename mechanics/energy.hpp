#pragma once
// The energy balance of a mechanical system (docs/numerics.md): kinetic energy (with the fluid's
// share where a body has added mass) + gravity potential + the energy every provider stores,
// minus the work of the non-conservative forces, is constant up to the integration error. Both
// sides iterate the system's one provider list; the set-point forces (servos, actor loads,
// prescribed motion) are non-conservative.
#include <Eigen/Core>

#include "dynamics/data.hpp"
#include "mechanics/data.hpp"
#include "mechanics/set_points.hpp"
#include "mechanics/system.hpp"

namespace yardsim::mechanics {

// (t, q, v; kin, one of d's kinematics workspaces, is overwritten with their kinematics) =>
// kinetic + gravity potential + stored energy of every provider, J
double energy(const System& s, const Data& d, dynamics::Data& kin, const Eigen::VectorXd& q,
              const Eigen::VectorXd& v, double t);
// (t, q, v; kin holding forwardKinematics(q, v), its draft-following added mass set here) => the
// same energy, J, without the kinematics pass
double energyAfterKinematics(const System& s, const Data& d, dynamics::Data& kin,
                             const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t);

// (t, q, v, set-points) => power of the non-conservative forces into the system, W: every
// provider's power, the servos' tau . v, the effort that enforces prescribed motion, and the
// actor loads' F . V; d.scratchKinematics(s, q, v) holds the kinematics of (q, v) afterwards
double nonConservativePower(const System& s, Data& d, const SetPoints& sp, const Eigen::VectorXd& q,
                            const Eigen::VectorXd& v, double t);

}  // namespace yardsim::mechanics
