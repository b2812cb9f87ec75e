#include "forces/hydro/forced_oscillation.hpp"

#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

#include "forces/hydro/emp_scheme.hpp"

namespace yardsim::forces::hydro {

RadiationCoefficients forcedOscillation(const RankineTdModel& model, int mode,
                                        const ForcedOscillationSettings& s) {
  if (mode < 0 || mode > 5 || !(s.omega > 0.0) || !(s.dt > 0.0) || s.periods <= s.rampPeriods ||
      s.analysisPeriods > s.periods - s.rampPeriods || s.analysisPeriods < 1) {
    throw std::invalid_argument(
        "forcedOscillation: mode 0..5, omega > 0, dt > 0, rampPeriods < periods, 1 <= "
        "analysisPeriods <= periods - rampPeriods");
  }
  const double period = 2.0 * std::numbers::pi / s.omega;
  const int perPeriod = static_cast<int>(std::ceil(period / s.dt));
  const double dt = period / perPeriod;
  const double ramp = s.rampPeriods * period;
  FreeSurfaceState state = quietSurface(model);
  EmpScratch scratch = makeEmpScratch(model);
  const Eigen::VectorXd normal = model.modes().col(mode);
  Eigen::VectorXd a(normal.size());
  const Eigen::VectorXd none;
  Eigen::Matrix<double, 6, 1> fs = Eigen::Matrix<double, 6, 1>::Zero(), fc = fs;
  Eigen::VectorXd zs = Eigen::VectorXd::Zero(state.zeta.size()), zc = zs;
  const int steps = s.periods * perPeriod, first = (s.periods - s.analysisPeriods) * perPeriod;
  for (int n = 0; n < steps; ++n) {
    // (t_n) => xi_dot of the ramped sine, the hull's normal velocity, the memory force
    const double t = n * dt;
    const double r = t < ramp ? 0.5 * (1.0 - std::cos(std::numbers::pi * t / ramp)) : 1.0;
    const double dr =
        t < ramp ? 0.5 * std::numbers::pi / ramp * std::sin(std::numbers::pi * t / ramp) : 0.0;
    const double xiDot =
        s.amplitude * (dr * std::sin(s.omega * t) + r * s.omega * std::cos(s.omega * t));
    a = xiDot * normal;
    const Eigen::Matrix<double, 6, 1> f = empStep(model, dt, a, none, state, scratch);
    if (n >= first) {
      fs += f * std::sin(s.omega * t);
      fc += f * std::cos(s.omega * t);
      // (zeta^n+1 lives at t_n + dt/2) => its sine and cosine sums
      const double th = s.omega * (t + 0.5 * dt);
      zs += std::sin(th) * state.zeta;
      zc += std::cos(th) * state.zeta;
    }
  }
  // (sums over whole periods) => Fourier coefficients, then A and B
  const double scale = 2.0 / (steps - first);
  RadiationCoefficients out;
  out.addedMass = model.aInf().col(mode) + scale * fs / (s.amplitude * s.omega * s.omega);
  out.damping = -scale * fc / (s.amplitude * s.omega);
  out.dt = dt;
  // (zeta = C cos + S sin) => Re((C - i S) e^{i w t})
  out.surfaceAmplitude =
      (scale / s.amplitude) * (zc.cast<std::complex<double>>() -
                               std::complex<double>(0.0, 1.0) * zs.cast<std::complex<double>>());
  return out;
}

}  // namespace yardsim::forces::hydro
