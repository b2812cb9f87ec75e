#pragma once
// The highest frequency a multibody system can excite, before it runs: the system is linearised
// at its initial state with every rope and equalizer taut (a slack rope is given an unstretched
// length just below its current length, since it may snap taut during the run), the Jacobian
// of (dq/dt, dv/dt) is taken by central finite differences of the accelerations (the stage
// function of system.hpp: every provider of the one list, and the servos of held joints), and
// omega_max is the largest eigenvalue modulus (a system with lumped-line nodes, which reports
// the structure of its Jacobian: J on that pattern by column colours and Arnoldi's method,
// largest_mode.hpp, linear in the nodes; any other: J dense and every eigenvalue), with the
// forces that have an analytic linearisation (catenary lines, linearisation.hpp) taking it. The
// mode is attributed to the body that moves
// most in it and to the provider (rope, equalizer, hydrostatics, ...) that stores most of its
// strain energy. A provider that brings stiffness in later (a contact open at the start,
// forces/provider_stiffness.hpp) states its own highest frequency; the larger one is reported.
#include <string>

#include "mechanics/description.hpp"
#include "mechanics/system.hpp"

namespace yardsim::mechanics {

struct StiffnessEstimate {
  double omegaMax = 0.0;      // rad/s, largest |eigenvalue| of the linearised first-order system
  double dampingRatio = 0.0;  // of that mode: -Re(lambda)/|lambda|
  std::string body;           // the body that moves most in that mode
  std::string element;        // the provider storing most of its strain energy ("" if none)
};

// (mechanics with their initial state) => the estimate; throws std::runtime_error when the
// accelerations at the initial state are not finite
StiffnessEstimate estimateStiffness(const BuiltMechanics& mech, const ServoSettings& servo = {});

// (estimate) => "omega_max = 119 rad/s, damping ratio 0.05 (body 'hook', rope 'hoist')"
std::string describe(const StiffnessEstimate& e);

}  // namespace yardsim::mechanics
