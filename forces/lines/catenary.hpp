#pragma once
// The quasi-static elastic catenary (Irvine, Cable Structures, 1981; the formulation of FAST v7,
// MAP++ and MoorPy): a line of unstretched length L, axial stiffness EA and weight per unit
// unstretched length w in water (w < 0: buoyant) from end A (the anchor) to end B (the
// fairlead), in the vertical plane through both ends. x is horizontal from A toward B, z is up.
// Given the spans XF >= 0 and ZF of B relative to A, it solves for the fairlead tension's
// components HF, VF (the line pulls B by -HF along x and -VF along z) by Newton iterations
// (warm-started from a guess) with the analytic 2x2 Jacobian, and reports the anchor tension,
// the touchdown point, the laid length, the profile, the stored energy and the stiffness.
//
// Sea bed: when `seabed` is set, A lies on a flat horizontal sea bed at A's height and a sinking
// line (w > 0) may rest on it from A up to the touchdown point, with Coulomb friction of
// coefficient CB, fully mobilised toward B (the FAST assumption): the tension grows from
// max(0, HF - CB w LB) at A to HF at touchdown. Profiles: fully suspended (also U-shaped,
// below A, and buoyant), touching down, lying fully on the bed (ZF = 0), and slack (the line
// longer than XF plus its hanging length: it hangs vertically under B, HF = 0).
// Units: m, N, N/m; EA may be +infinity (inextensible).

namespace yardsim::forces {

struct CatenaryParameters {
  double length = 0.0;    // L, unstretched, m (> 0)
  double ea = 0.0;        // EA, N (> 0, may be +infinity)
  double weight = 0.0;    // w, submerged weight per unit unstretched length, N/m (!= 0)
  bool seabed = false;    // A lies on the sea bed and the line may rest on it (w > 0)
  double friction = 0.0;  // CB, sea-bed friction coefficient (>= 0; with seabed only)
};

enum class CatenaryProfile { Suspended, TouchingDown, OnSeabed, Slack };

enum class CatenaryStatus { Converged, NoConvergence, BelowSeabed, BadInput };

struct CatenarySolution {
  double hf = 0.0, vf = 0.0;  // fairlead tension components, N (line pulls B by -hf x, -vf z)
  double ha = 0.0, va = 0.0;  // anchor tension components, N (line pulls A by +ha x, +va z)
  double laidLength = 0.0;    // LB, unstretched length resting on the sea bed, m
  double touchdownX = 0.0;    // horizontal distance from A to the touchdown point, m
  // d(HF, VF)/d(XF, ZF), row-major: [dHF/dXF, dHF/dZF; dVF/dXF, dVF/dZF], N/m
  double k11 = 0.0, k12 = 0.0, k21 = 0.0, k22 = 0.0;
  CatenaryProfile profile = CatenaryProfile::Suspended;
  CatenaryStatus status = CatenaryStatus::BadInput;
  int iterations = 0;
};

// A point of the line's profile at unstretched arc length s from A: x, z relative to A (m) and
// the effective tension T (N).
struct CatenaryPoint {
  double x = 0.0, z = 0.0, tension = 0.0;
};

// (parameters) => "" when valid, else what is wrong (for the callers' messages)
const char* catenaryParameterError(const CatenaryParameters& p);

// (parameters, XF >= 0, ZF, guess (hf, vf) or hf <= 0 for a cold start) => the solution. Newton
// on (HF, VF) with HF kept positive, step halving when the residual grows, at most 100
// iterations; converged when the span residual is below 1e-12 (L + XF + |ZF|), or below 1e-9
// (L + XF + |ZF|) once the step is below 1e-13 of the forces (the rounding floor of a very taut,
// nearly inextensible line). Allocation-free.
CatenarySolution solveCatenary(const CatenaryParameters& p, double xf, double zf, double hf0 = 0.0,
                               double vf0 = 0.0);

// (parameters, a solution, s in [0, L]) => the point at unstretched arc length s from A
CatenaryPoint catenaryPoint(const CatenaryParameters& p, const CatenarySolution& sol, double xf,
                            double s);

// (parameters, a solution) => the energy stored in the line relative to A's height: its weight
// w times the integral of z ds plus its strain energy, integral of T^2 / (2 EA) ds, J. For a line
// without friction dV/dXF = HF and dV/dZF = VF (the line is conservative); with friction it is
// not.
double catenaryEnergy(const CatenaryParameters& p, const CatenarySolution& sol);

}  // namespace yardsim::forces
