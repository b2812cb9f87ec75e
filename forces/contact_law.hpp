#pragma once
// The compliant contact law: a penalty normal force from the penetration depth and its rate, and
// regularised Coulomb friction from the tangential slip velocity. Pure functions of one contact
// point, no bodies and no geometry: the collision kernel (block on ground, on supports, on a
// deck, fenders) and the sea-bed contact of mooring lines feed the same law. docs/collision.md
// gives the formulas and the restitution relations.
//
// Units (SI): depth delta [m] (> 0 in penetration), depth rate delta_dot [m/s] (> 0 while
// approaching), slip velocity v_t [m/s] (the velocity of B relative to A at the contact point,
// tangential part, any frame: the force comes back in the same frame), stiffness k [N/m^n],
// damping c [N s/m^(n+1)] (linear law: N s/m), forces [N], energy [J], power [W].
//
// Normal laws (both never pull: F_n = max(0, ...), and F_n = 0 for delta <= 0):
//   linear spring-damper   F_n = k delta + c min(1, delta / delta_0) delta_dot: the damping is
//                          ramped in over the first delta_0 of penetration (MSC Adams' IMPACT
//                          does the same with a cubic step), so the force is continuous where
//                          the contact closes (delta_0 = 0: the plain law, whose force jumps
//                          from 0 to c delta_dot there and which an implicit step cannot cross)
//   Hunt-Crossley          F_n = k delta^n + c delta^n delta_dot = k delta^n (1 + alpha delta_dot),
//                          alpha = c / k [s/m]; n = 1.5 is Hertz's exponent for curved bodies,
//                          n = 1 for flat faces.
// Potential energy of the penalty spring: k delta^(n+1) / (n + 1) (linear: n = 1).
// Power of the non-conservative part into the system (<= 0): -(F_n - k delta^n) delta_dot, the
// damping and the clamp, plus F_t . v_t for friction.
//
// Regularised Coulomb friction (stick becomes a steep viscous creep below the slip speed v_s):
//   sqrt form  F_t = -mu F_n v_t / sqrt(|v_t|^2 + v_s^2)
//   tanh form  F_t = -mu F_n tanh(|v_t| / v_s) v_t / |v_t|
// Both reach mu F_n for |v_t| >> v_s and behave as a viscous damper of slope mu F_n / v_s near
// zero slip: a block on an incline below tan(phi) = mu creeps at a speed of order v_s.
#include "dynamics/spatial.hpp"

namespace yardsim::forces {

enum class NormalLawKind { kLinear, kHuntCrossley };

// Parameters of the normal law; units above. For kLinear the exponent is ignored (n = 1).
struct NormalLaw {
  NormalLawKind kind = NormalLawKind::kHuntCrossley;
  double stiffness = 1e9;     // k, N/m^n
  double damping = 0.0;       // c, N s/m^(n+1) (Hunt-Crossley: c = alpha k), linear: N s/m
  double exponent = 1.5;      // n, Hunt-Crossley only
  double dampingDepth = 0.0;  // delta_0, m, linear only: the damping's ramp (0: no ramp)
};

enum class FrictionForm { kSqrt, kTanh };

struct FrictionLaw {
  double mu = 0.0;          // Coulomb coefficient, -
  double slipSpeed = 1e-3;  // v_s, m/s, > 0
  FrictionForm form = FrictionForm::kSqrt;
};

// One contact point's forces, energy and power.
struct ContactResponse {
  double normalForce = 0.0;  // F_n >= 0, N, pushes A and B apart
  dynamics::Vector3 tangentialForce = dynamics::Vector3::Zero();  // F_t on B, N (-F_t on A)
  double potentialEnergy = 0.0;                                   // J, stored in the penalty spring
  double power = 0.0;  // W, non-conservative power into the system (<= 0)
};

// (law, delta m, delta_dot m/s) => F_n >= 0, N
double normalForce(const NormalLaw& law, double depth, double depthRate);
// (law, delta m) => the elastic part k delta^n alone, N (>= 0)
double elasticForce(const NormalLaw& law, double depth);
// (law, delta m) => k delta^(n+1) / (n + 1), J (0 for delta <= 0)
double potentialEnergy(const NormalLaw& law, double depth);
// (law, delta, delta_dot) => -(F_n - k delta^n) delta_dot, W: the normal law's dissipation (<= 0)
double normalPower(const NormalLaw& law, double depth, double depthRate);
// (friction, F_n N, v_t m/s) => F_t on B, N, opposing v_t, |F_t| <= mu F_n
dynamics::Vector3 frictionForce(const FrictionLaw& friction, double normalForce,
                                const dynamics::Vector3& slipVelocity);
// (normal law, friction, delta, delta_dot, v_t) => F_n, F_t, the spring's energy and the power
ContactResponse contactResponse(const NormalLaw& law, const FrictionLaw& friction, double depth,
                                double depthRate, const dynamics::Vector3& slipVelocity);

// Restitution of an impact at speed v0 (no other force, rigid otherwise), for choosing c.
// (k, e in (0, 1], v0 m/s) => Hunt-Crossley c = alpha k with Lankarani-Nikravesh
// alpha = 3 (1 - e^2) / (4 v0) (good for e near 1)
double lankaraniNikraveshDamping(double stiffness, double restitution, double impactSpeed);
// (alpha v0 = c v0 / k >= 0) => the exact coefficient of restitution e of the Hunt-Crossley law
// (any exponent n, any mass): the root in (0, 1] of ln((1 + a) / (1 - a e)) = a (1 + e), from
// integrating m v dv / (1 + alpha v) = -k delta^n d delta over the impact
double huntCrossleyRestitution(double alphaV0);
// (m kg, k N/m, c N s/m) => the linear law's e when contact ends at F_n = 0 (the clamp: the
// damped oscillator's velocity when its acceleration first vanishes); needs zeta < 1. The
// unclamped textbook value exp(-zeta pi / sqrt(1 - zeta^2)) (contact until delta = 0) is smaller
double linearRestitution(double mass, double stiffness, double damping);
// (m kg, linear law with its ramp delta_0 >= 0, v0 m/s > 0) => e of a 1-dof impact at v0 (no
// other force), piecewise exact: on the ramp the law is Hunt-Crossley with n = 1 and
// alpha = c / (k delta_0), whose m v dv / (1 + alpha v) = -k delta d delta integrates in closed
// form; beyond it the damped oscillator (zeta < 1), its end at delta = delta_0 or at F_n = 0 found
// by bisection on the closed-form motion. delta_0 = 0: linearRestitution; a contact that stays on
// the ramp: huntCrossleyRestitution(alpha v0)
double rampedLinearRestitution(double mass, const NormalLaw& law, double impactSpeed);

}  // namespace yardsim::forces
