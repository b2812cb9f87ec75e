#include "forces/hydro/regular_wave_run.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "dynamics/added_mass.hpp"
#include "dynamics/integrators/rk4.hpp"
#include "dynamics/model_builder.hpp"
#include "dynamics/multibody_system.hpp"
#include "forces/airy_waves.hpp"
#include "forces/hydro/emp_scheme.hpp"
#include "forces/hydro/rankine_td_provider.hpp"

namespace yardsim::forces::hydro {

Eigen::Matrix<double, 6, 6> rigidBodyMass(const RigidBody& b) {
  // (spatial inertia [angular; linear]) => naval [linear; angular]
  const dynamics::Matrix6 I = dynamics::makeInertia(b.mass, b.com, b.inertiaCom).matrix();
  Eigen::Matrix<double, 6, 6> M;
  M << I.bottomRightCorner<3, 3>(), I.bottomLeftCorner<3, 3>(), I.topRightCorner<3, 3>(),
      I.topLeftCorner<3, 3>();
  return M;
}

Eigen::Matrix<std::complex<double>, 6, 1> measuredResponse(
    std::shared_ptr<const RankineTdModel> panels, const RigidBody& body,
    const Eigen::Matrix<double, 6, 6>& restoring, const RegularWaveRun& run) {
  const auto& modes = run.freeModes;
  for (std::size_t i = 0; i < modes.size(); ++i)
    if (modes[i] < 0 || modes[i] > 5 || (i > 0 && modes[i] <= modes[i - 1]))
      throw std::invalid_argument("measuredResponse: free modes must be increasing in 0..5");
  if (modes.empty() || !(run.omega > 0.0) || !(run.amplitude > 0.0) ||
      run.periods <= run.rampPeriods || run.analysisPeriods < 1 ||
      run.analysisPeriods > run.periods - run.rampPeriods)
    throw std::invalid_argument(
        "measuredResponse: modes, omega, amplitude or periods out of range");
  const double period = 2.0 * std::numbers::pi / run.omega;
  const double limit = 0.45 * empLimit(*panels, 60).dtMax;
  const double wanted = run.step > 0.0 ? run.step : std::min(period / 40.0, limit);
  const int perPeriod = static_cast<int>(std::ceil(period / wanted));
  const double h = period / perPeriod;
  // (free modes) => a chain of joints from the world to the hull; the links between carry 1e-9
  // of the hull's mass and inertia (the kernel wants positive masses; 1e-9 changes nothing seen)
  dynamics::ModelBuilder b;
  b.setGravity(Vector3::Zero());  // weight and buoyancy balance at the mean pose: C alone restores
  std::string parent = "world";
  const dynamics::SpatialInertia none =
      dynamics::makeInertia(1e-9 * body.mass, Vector3::Zero(), 1e-9 * body.inertiaCom);
  for (std::size_t i = 0; i < modes.size(); ++i) {
    const int m = modes[i];
    const Vector3 axis = Vector3::Unit(m % 3);
    const dynamics::Joint j =
        m < 3 ? dynamics::Joint::prismatic(axis) : dynamics::Joint::revolute(axis);
    const bool last = i + 1 == modes.size();
    const std::string name = last ? "hull" : "link" + std::to_string(i);
    b.addBody(name, parent, j, dynamics::Transform::identity(),
              last ? dynamics::makeInertia(body.mass, body.com, body.inertiaCom) : none);
    parent = name;
  }
  const RankineTdModel::Matrix6 aInf = panels->aInf();
  b.setAddedMass("hull",
                 dynamics::addedMassAboutOrigin(0.5 * (aInf + aInf.transpose()), Vector3::Zero()));
  const dynamics::Model model = b.build();
  const int hull = model.nbodies - 1, n = static_cast<int>(modes.size());
  // (one regular wave with its crest at the origin at t = 0, ramped) => the provider
  forces::WaterProperties water;
  water.density = panels->settings().rho;
  water.gravity = panels->settings().g;
  water.depth = panels->settings().depth;
  water.ramp = run.rampPeriods * period;
  const auto sea = std::make_shared<const forces::AiryWaves>(
      water, std::vector<forces::WaveComponent>{{2.0 * run.amplitude, period, run.heading, 0.0}});
  const RankineTdProvider provider("rankine_td", model, hull, panels, h, sea, true);
  auto scratch = provider.makeScratch();
  dynamics::MultibodySystem system(model);
  double stepStart = 0.0;
  system.setForces([&](double ts, const Eigen::VectorXd& qs, const Eigen::VectorXd& vs,
                       const dynamics::Data& d, dynamics::ExternalForces& f, Eigen::VectorXd& tau) {
    // (joint coordinates = the free modes' displacements and rates) => -C xi - D xi_dot
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) {
        const auto i = modes[static_cast<std::size_t>(r)], j = modes[static_cast<std::size_t>(c)];
        tau[r] -= restoring(i, j) * qs[c] + run.damping(i, j) * vs[c];
      }
    provider.evaluate(forces::Stage{ts, model, d, qs, vs, scratch.get(), stepStart}, f, tau);
  });
  dynamics::Rk4 rk4(model);
  double t = 0.0;
  Eigen::VectorXd q = Eigen::VectorXd::Zero(n), v = Eigen::VectorXd::Zero(n);
  const int steps = run.periods * perPeriod,
            first = (run.periods - run.analysisPeriods) * perPeriod;
  // (samples after `first`) => normal equations of the fit [1, t, cos, sin] per mode
  Eigen::Matrix4d normal = Eigen::Matrix4d::Zero();
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(4, n);
  for (int s = 0; s < steps; ++s) {
    stepStart = t;
    rk4.step(system, t, q, v, h);
    if (s + 1 <= first) continue;
    const double tl = t - first * h;  // local time keeps the fit well conditioned
    const Eigen::Vector4d phi(1.0, tl, std::cos(run.omega * t), std::sin(run.omega * t));
    normal += phi * phi.transpose();
    rhs += phi * q.transpose();
  }
  const Eigen::MatrixXd coef = normal.ldlt().solve(rhs);
  // (xi = C cos + S sin) => Re((C - i S) e^{i w t}), per unit wave amplitude
  Eigen::Matrix<std::complex<double>, 6, 1> out = Eigen::Matrix<std::complex<double>, 6, 1>::Zero();
  for (int r = 0; r < n; ++r)
    out[modes[static_cast<std::size_t>(r)]] =
        std::complex<double>(coef(2, r), -coef(3, r)) / run.amplitude;
  return out;
}

}  // namespace yardsim::forces::hydro
