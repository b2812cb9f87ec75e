#include "forces/contact_law.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace yardsim::forces {

namespace {

// (law, delta > 0) => delta^n (n = 1 for the linear law)
double powDepth(const NormalLaw& law, double depth) {
  return law.kind == NormalLawKind::kLinear ? depth : std::pow(depth, law.exponent);
}

}  // namespace

// (law, delta) => k delta^n
double elasticForce(const NormalLaw& law, double depth) {
  if (depth <= 0.0) return 0.0;
  return law.stiffness * powDepth(law, depth);
}

// (law, delta, delta_dot) => max(0, k delta^n + c delta^n delta_dot) (linear:
// c min(1, delta / delta_0) delta_dot)
double normalForce(const NormalLaw& law, double depth, double depthRate) {
  if (depth <= 0.0) return 0.0;
  const double dn = powDepth(law, depth);
  const double ramp = depth < law.dampingDepth ? depth / law.dampingDepth : 1.0;
  const double damping = law.kind == NormalLawKind::kLinear ? law.damping * ramp * depthRate
                                                            : law.damping * dn * depthRate;
  return std::max(0.0, law.stiffness * dn + damping);
}

// (law, delta) => k delta^(n+1) / (n+1)
double potentialEnergy(const NormalLaw& law, double depth) {
  if (depth <= 0.0) return 0.0;
  const double n = law.kind == NormalLawKind::kLinear ? 1.0 : law.exponent;
  return law.stiffness * std::pow(depth, n + 1.0) / (n + 1.0);
}

// (law, delta, delta_dot) => -(F_n - k delta^n) delta_dot
double normalPower(const NormalLaw& law, double depth, double depthRate) {
  if (depth <= 0.0) return 0.0;
  return -(normalForce(law, depth, depthRate) - elasticForce(law, depth)) * depthRate;
}

// (friction, F_n, v_t) => -mu F_n v_t / sqrt(|v_t|^2 + v_s^2) or the tanh form
dynamics::Vector3 frictionForce(const FrictionLaw& friction, double normalForceN,
                                const dynamics::Vector3& slipVelocity) {
  if (friction.mu <= 0.0 || normalForceN <= 0.0) return dynamics::Vector3::Zero();
  const double speed = slipVelocity.norm();
  const double vs = friction.slipSpeed;
  if (friction.form == FrictionForm::kSqrt) {
    return (-friction.mu * normalForceN / std::sqrt(speed * speed + vs * vs)) * slipVelocity;
  }
  // tanh(s / v_s) / s -> 1 / v_s as s -> 0: the same viscous slope as the sqrt form
  const double x = speed / vs;
  const double gain = x < 1e-8 ? 1.0 / vs : std::tanh(x) / speed;
  return (-friction.mu * normalForceN * gain) * slipVelocity;
}

// (laws, delta, delta_dot, v_t) => F_n, F_t, energy, power
ContactResponse contactResponse(const NormalLaw& law, const FrictionLaw& friction, double depth,
                                double depthRate, const dynamics::Vector3& slipVelocity) {
  ContactResponse r;
  if (depth <= 0.0) return r;
  r.normalForce = normalForce(law, depth, depthRate);
  r.tangentialForce = frictionForce(friction, r.normalForce, slipVelocity);
  r.potentialEnergy = potentialEnergy(law, depth);
  r.power =
      -(r.normalForce - elasticForce(law, depth)) * depthRate + r.tangentialForce.dot(slipVelocity);
  return r;
}

// (k, e, v0) => c = k 3 (1 - e^2) / (4 v0)
double lankaraniNikraveshDamping(double stiffness, double restitution, double impactSpeed) {
  if (!(impactSpeed > 0.0) || !(restitution > 0.0) || restitution > 1.0) {
    throw std::invalid_argument("lankaraniNikraveshDamping: needs v0 > 0 and 0 < e <= 1");
  }
  return stiffness * 3.0 * (1.0 - restitution * restitution) / (4.0 * impactSpeed);
}

// (a = alpha v0) => e in (0, 1]: root of g(e) = ln(1 + a) - ln(1 - a e) - a (1 + e), by bisection
double huntCrossleyRestitution(double alphaV0) {
  const double a = alphaV0;
  if (!(a >= 0.0) || !std::isfinite(a)) {
    throw std::invalid_argument("huntCrossleyRestitution: needs alpha v0 >= 0");
  }
  if (a < 1e-12) return 1.0;
  // g(0) = ln(1 + a) - a < 0, g(min(1, 1/a)) > 0 or the bracket's end; g is increasing in e
  auto g = [a](double e) { return std::log1p(a) - std::log1p(-a * e) - a * (1.0 + e); };
  double lo = 0.0;
  double hi = std::min(1.0, (1.0 - 1e-15) / a);
  if (g(hi) < 0.0) return hi;
  for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
    const double mid = 0.5 * (lo + hi);
    (g(mid) < 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// (m, k, c) => e = exp(-sigma t*) (sigma sin th - w_d cos th) / w_d, th = w_d t* = atan2(2 sigma
// w_d, sigma^2 - w_d^2): the damped oscillator x = v0/w_d e^(-sigma t) sin(w_d t) at x'' = 0
double linearRestitution(double mass, double stiffness, double damping) {
  const double wn = std::sqrt(stiffness / mass);
  const double zeta = damping / (2.0 * std::sqrt(stiffness * mass));
  if (!(zeta >= 0.0) || zeta >= 1.0) {
    throw std::invalid_argument("linearRestitution: needs 0 <= zeta < 1");
  }
  const double sigma = zeta * wn;
  const double wd = wn * std::sqrt(1.0 - zeta * zeta);
  const double th = std::atan2(2.0 * sigma * wd, sigma * sigma - wd * wd);
  return std::exp(-sigma * th / wd) * (sigma * std::sin(th) - wd * std::cos(th)) / wd;
}

namespace {

// (root bracket [lo, hi] with f(lo), f(hi) of opposite signs) => the root, by bisection
template <class F>
double bisect(F f, double lo, double hi) {
  const bool rising = f(lo) < 0.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    ((f(mid) < 0.0) == rising ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

// (m, law, v0) => e: ramp (Hunt-Crossley n = 1), oscillator, ramp; see the header
double rampedLinearRestitution(double mass, const NormalLaw& law, double impactSpeed) {
  const double m = mass, k = law.stiffness, c = law.damping, d0 = law.dampingDepth;
  const double v0 = impactSpeed;
  if (law.kind != NormalLawKind::kLinear || !(v0 > 0.0) || !(d0 >= 0.0)) {
    throw std::invalid_argument(
        "rampedLinearRestitution: needs a linear law, v0 > 0, delta_0 >= 0");
  }
  if (d0 == 0.0 || c == 0.0) return linearRestitution(m, k, c);
  // on the ramp: G(v) = m (alpha v - ln(1 + alpha v)) / alpha^2, G(v) + k delta^2 / 2 constant
  const double alpha = c / (k * d0);
  auto G = [&](double v) { return m * (alpha * v - std::log1p(alpha * v)) / (alpha * alpha); };
  const double rampEnergy = 0.5 * k * d0 * d0;
  if (G(v0) <= rampEnergy) return huntCrossleyRestitution(alpha * v0);  // never leaves the ramp
  const double v1 = bisect([&](double v) { return G(v) - (G(v0) - rampEnergy); }, 0.0, v0);
  // beyond: x = e^(-sigma t) (d0 cos(w_d t) + B sin(w_d t)), from (d0, v1)
  const double wn = std::sqrt(k / m);
  const double zeta = c / (2.0 * std::sqrt(k * m));
  if (zeta >= 1.0) throw std::invalid_argument("rampedLinearRestitution: needs zeta < 1");
  const double sigma = zeta * wn, wd = wn * std::sqrt(1.0 - zeta * zeta);
  const double B = (v1 + sigma * d0) / wd;
  auto x = [&](double t) {
    return std::exp(-sigma * t) * (d0 * std::cos(wd * t) + B * std::sin(wd * t));
  };
  auto v = [&](double t) {
    return std::exp(-sigma * t) *
           ((B * wd - sigma * d0) * std::cos(wd * t) - (d0 * wd + sigma * B) * std::sin(wd * t));
  };
  auto force = [&](double t) { return k * x(t) + c * v(t); };
  // the first of x = d0 (after the turn) and F = 0, scanning half a period in fine steps
  const double dt = M_PI / wd / 4000.0;
  double t = dt;
  while (x(t) > d0 && force(t) > 0.0) t += dt;
  if (force(t) <= 0.0) return -v(bisect(force, t - dt, t)) / v0;  // the clamp lets go
  const double v2 = v(bisect([&](double s) { return x(s) - d0; }, t - dt, t));
  // back on the ramp to delta = 0: G(v3) = G(v2) + k d0^2 / 2, v3 in (-1/alpha, v2)
  const double target = G(v2) + rampEnergy;
  const double v3 = bisect([&](double s) { return G(s) - target; }, -(1.0 - 1e-15) / alpha, v2);
  return -v3 / v0;
}

}  // namespace yardsim::forces
