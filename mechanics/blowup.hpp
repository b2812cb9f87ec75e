#pragma once
// Blow-up diagnosis (docs/numerics.md): after every step the state must be finite, the energy
// balance (energy.hpp: energy - work of the non-conservative forces, constant up to the
// integration error) must not rise beyond a bound, and the loops must stay closed. A failure is
// a BlowUp naming the body or force element, what happened and the likely cause.
#include <stdexcept>
#include <string>

#include <Eigen/Core>

#include "mechanics/data.hpp"
#include "mechanics/system.hpp"

namespace yardsim::mechanics {

class BlowUp : public std::runtime_error {
 public:
  BlowUp(std::string where, const std::string& what, std::string fix)
      : std::runtime_error(what), element(std::move(where)), suggestion(std::move(fix)) {}
  std::string element;     // ", body 'hook' (joint 'hook_joint')", ", loop 'l1'"
  std::string suggestion;  // what to try instead
};

struct BlowUpLimits {
  double energyBound = 0.0;         // J: largest rise of the energy balance
  double balance0 = 0.0;            // J: the energy balance at the start
  double loopResidualLimit = 1e-3;  // m or rad
  bool projectLoops = true;
  std::string method;  // the integrator, for the likely cause
  double dt = 0.0;     // s
};

// (initial q, v) => the energy scale of the blow-up bound, J: total weight x the system's size,
// plus its kinetic and strain energy
double energyScale(const System& s, Data& d, const Eigen::VectorXd& q, const Eigen::VectorXd& v);

// (system at its start, method, step) => the likely cause of a blow-up: omega_max dt against the
// method's stability limit
std::string likelyCause(const System& s, const std::string& method, double dt);

// (state after a step to t, the work so far) => throws BlowUp when it is not finite, its energy
// balance grew beyond the bound or a loop opened; else its energy (energyAfterKinematics), J
double checkBlowUp(const System& s, Data& d, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                   double work, double t, const BlowUpLimits& limits);

}  // namespace yardsim::mechanics
