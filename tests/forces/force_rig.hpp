#pragma once
// Test support for the force providers: a model stepped by RK4 (dynamics::MultibodySystem) with
// providers evaluated at every integrator stage, the stage at the current state, and the energy
// balance kinetic + potential - integral(power) dt with the integral by composite Simpson.
#include <cmath>
#include <vector>

#include "dynamics/configuration.hpp"
#include "dynamics/energy.hpp"
#include "dynamics/integrators/rk4.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/model_builder.hpp"
#include "dynamics/multibody_system.hpp"
#include "forces/force_provider.hpp"

namespace yardsim::forces::testing {

using dynamics::Vector3;

// A block of mass m on a vertical prismatic joint (q = height of its origin, m), no model gravity.
inline dynamics::Model verticalBlock(double m, const Vector3& gravity = Vector3::Zero()) {
  dynamics::ModelBuilder b;
  b.setGravity(gravity);
  b.addBody("block", "world", dynamics::Joint::prismatic(Vector3::UnitZ()),
            dynamics::Transform::identity(), dynamics::boxInertia(m, Vector3(2.0, 2.0, 1.0)));
  return b.build();
}

class Rig {
 public:
  Rig(const dynamics::Model& model, std::vector<ForceProvider*> providers)
      : model_(model),
        providers_(std::move(providers)),
        system_(model),
        rk4_(model),
        data_(model),
        q(dynamics::neutralConfiguration(model)),
        v(Eigen::VectorXd::Zero(model.nv)) {
    system_.setForces([this](double ts, const Eigen::VectorXd& qs, const Eigen::VectorXd& vs,
                             const dynamics::Data& d, dynamics::ExternalForces& f,
                             Eigen::VectorXd& tau) {
      const Stage s{ts, model_, d, qs, vs};
      for (ForceProvider* p : providers_) p->evaluate(s, f, tau);
    });
  }

  void step(double h) { rk4_.step(system_, t, q, v, h); }
  // (q, v, t) => the stage a provider sees there
  Stage stage() {
    dynamics::forwardKinematics(model_, data_, q, v);
    return {t, model_, data_, q, v};
  }
  // (q, v, t) => kinetic + sum of the providers' potential energies, J
  double energy() {
    double e = dynamics::kineticEnergy(model_, data_, q, v);
    const Stage s = stage();
    for (const ForceProvider* p : providers_) e += p->potentialEnergy(s);
    return e;
  }
  // (q, v, t) => sum of the providers' powers, W
  double power() {
    const Stage s = stage();
    double w = 0.0;
    for (const ForceProvider* p : providers_) w += p->power(s);
    return w;
  }
  // (h, an even number of steps) => max over even steps of |E(t) - E(0) - integral(power)|,
  // with the integral by composite Simpson on the step ends; also the largest |integral|
  struct Balance {
    double maxError = 0.0;
    double maxWork = 0.0;
  };
  Balance energyBalance(double h, int steps) {
    const double e0 = energy();
    double work = 0.0, p0 = power();
    Balance b;
    for (int k = 0; k < steps; k += 2) {
      step(h);
      const double p1 = power();
      step(h);
      const double p2 = power();
      work += h / 3.0 * (p0 + 4.0 * p1 + p2);
      p0 = p2;
      b.maxError = std::max(b.maxError, std::abs(energy() - e0 - work));
      b.maxWork = std::max(b.maxWork, std::abs(work));
    }
    return b;
  }

  double t = 0.0;

 private:
  const dynamics::Model& model_;
  std::vector<ForceProvider*> providers_;
  dynamics::MultibodySystem system_;
  dynamics::Rk4 rk4_;
  dynamics::Data data_;

 public:
  Eigen::VectorXd q, v;
};

}  // namespace yardsim::forces::testing
