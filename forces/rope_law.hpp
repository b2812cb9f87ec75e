#pragma once
// The constitutive law of a steel wire rope, shared by the wire rope and the equalizer: a
// tension-only spring-damper whose stiffness EA/L0 follows the current unstretched length L0.
// Per part:  T = max(0, EA/L0 (L - L0) + c d(L - L0)/dt)  while L > L0, else 0,
// strain energy V = EA/(2 L0) (L - L0)^2 while L > L0, else 0.
#include <optional>
#include <string>

namespace yardsim::forces {

// The material of one rope part. SI units.
struct RopeProperties {
  double ea = 0.0;          // axial stiffness EA of one part, N
  double l0 = 0.0;          // unstretched length at the start, m
  double damping = 0.0;     // viscous damping c on the elongation rate, N s/m
  double minLength = 0.01;  // shortest unstretched length a winch can haul in to, m
  std::optional<double>
      breakingLoad;  // minimum breaking load MBL of one part, N (not checked if empty)
};

// (properties, owner name) => nothing, or std::invalid_argument naming the owner and the parameter
void checkRopeProperties(const RopeProperties& p, const std::string& owner);

// The kinematic state of one part: stretched length L, its rate, unstretched length L0, its rate.
struct RopeStrain {
  double length = 0.0;
  double lengthRate = 0.0;
  double l0 = 0.0;
  double l0Rate = 0.0;
};

// (EA, strain) => elastic tension EA/L0 (L - L0) when taut, else 0, N
double elasticTension(double ea, const RopeStrain& s);
// (EA, c, strain) => tension of one part, >= 0 (a slack rope never pushes, damping never makes it
// push), N
double ropeTension(double ea, double c, const RopeStrain& s);
// (EA, L, L0) => strain energy of one part, J
double strainEnergy(double ea, double length, double l0);
// (EA, L, L0) => dV/dL0 of one part at fixed L, J/m
double strainEnergyDl0(double ea, double length, double l0);
// (EA, tension T actually applied, parts n, strain) => power of the rope's non-conservative
// part: -n (T - T_elastic) dL/dt + n dV/dL0 dL0/dt, W; with it, kinetic + n V - integral(power)
// is constant
double ropePower(double ea, double tension, int parts, const RopeStrain& s);

}  // namespace yardsim::forces
