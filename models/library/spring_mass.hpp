#pragma once
// Scene type `spring_mass`: a mass on a linear spring and damper, m x'' + c x' + k x = F,
// stepped as a DTSS model with explicit Euler, semi-implicit Euler or RK4 at step dt. The
// smallest physical scene: it exercises the DTSS rules, records x, v and energy, and a step
// beyond the method's stability limit blows up into a numerical failure with a diagnosis.
#include <array>
#include <ostream>
#include <string>
#include <tuple>

#include "dtss/atomic.hpp"
#include "models/channels.hpp"

namespace yardsim::models::library {

struct SpringMassState {
  double x = 0.0;  // m
  double v = 0.0;  // m/s
  double force = 0.0;  // N, external, set by input
};
std::ostream& operator<<(std::ostream& os, const SpringMassState& s);

}  // namespace yardsim::models::library

namespace yardsim::devs {
template <>
struct StateCodec<models::library::SpringMassState> : FieldCodec<models::library::SpringMassState> {
  static auto fields(auto& s) { return std::tie(s.x, s.v, s.force); }
};
}  // namespace yardsim::devs

namespace yardsim::models::library {

enum class StepMethod { Euler, SymplecticEuler, Rk4 };

struct SpringMassParams {
  double mass, stiffness, damping, x0, v0, dt;
  StepMethod method;
  double blowupLimit;  // |x| beyond this (m) is a numerical failure
};

class SpringMass final : public dtss::Atomic<SpringMassState>, public Observable {
 public:
  SpringMass(std::string name, const SpringMassParams& p);
  devs::InPort<double>& force = addInPort<double>("force");
  devs::OutPort<double>& upcrossing = addOutPort<double>("upcrossing");
  void channels(std::vector<Channel>& out) const override;
  double energy(const SpringMassState& s) const;

 protected:
  void advance(SpringMassState& s, devs::Time t, devs::Time dt) const override;
  void applyInput(SpringMassState& s, devs::Time t) const override;
  std::span<const dtss::Crossing> eventDirections() const override { return dirs_; }
  void eventFunctions(const SpringMassState& s, devs::Time, std::span<double> g) const override;
  void outputAt(const SpringMassState& s, devs::Time t, const dtss::Reached& r) const override;

 private:
  SpringMassParams p_;
  std::array<dtss::Crossing, 1> dirs_{dtss::Crossing::Rising};
};

}  // namespace yardsim::models::library
