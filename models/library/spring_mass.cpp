#include "models/library/spring_mass.hpp"

#include <cmath>

#include "models/numerical_error.hpp"
#include "models/registry.hpp"

namespace yardsim::models::library {

std::ostream& operator<<(std::ostream& os, const SpringMassState& s) {
  return os << "x=" << s.x << " v=" << s.v;
}

SpringMass::SpringMass(std::string name, const SpringMassParams& p)
    : dtss::Atomic<SpringMassState>(std::move(name), SpringMassState{p.x0, p.v0, 0.0}, p.dt),
      p_(p) {}

double SpringMass::energy(const SpringMassState& s) const {
  return 0.5 * p_.mass * s.v * s.v + 0.5 * p_.stiffness * s.x * s.x;
}

void SpringMass::channels(std::vector<Channel>& out) const {
  out.push_back({"x", "m", [this] { return state().x.x; }});
  out.push_back({"v", "m/s", [this] { return state().x.v; }});
  out.push_back({"energy", "J", [this] { return energy(state().x); }});
}

void SpringMass::advance(SpringMassState& s, devs::Time t, devs::Time dt) const {
  // (x, v) => acceleration
  auto acc = [&](double x, double v) {
    return (s.force - p_.stiffness * x - p_.damping * v) / p_.mass;
  };
  switch (p_.method) {
    case StepMethod::Euler: {
      const double a = acc(s.x, s.v);
      s.x += dt * s.v;
      s.v += dt * a;
      break;
    }
    case StepMethod::SymplecticEuler:
      s.v += dt * acc(s.x, s.v);
      s.x += dt * s.v;
      break;
    case StepMethod::Rk4: {
      const double k1x = s.v, k1v = acc(s.x, s.v);
      const double k2x = s.v + 0.5 * dt * k1v, k2v = acc(s.x + 0.5 * dt * k1x, k2x);
      const double k3x = s.v + 0.5 * dt * k2v, k3v = acc(s.x + 0.5 * dt * k2x, k3x);
      const double k4x = s.v + dt * k3v, k4v = acc(s.x + dt * k3x, k4x);
      s.x += dt / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x);
      s.v += dt / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
      break;
    }
  }
  if (!std::isfinite(s.x) || !std::isfinite(s.v) || std::abs(s.x) > p_.blowupLimit) {
    const double omega = std::sqrt(p_.stiffness / p_.mass);
    throw NumericalError(
        "spring_mass '" + path() + "'", t + dt,
        "displacement " + std::to_string(s.x) + " m left the bound " +
            std::to_string(p_.blowupLimit) + " m (omega*dt = " + std::to_string(omega * p_.dt) + ")",
        "a smaller dt (RK4 is stable for omega*dt < 2.83, explicit Euler never for an undamped "
        "spring) or method symplectic_euler (stable for omega*dt < 2)");
  }
}

void SpringMass::applyInput(SpringMassState& s, devs::Time) const { s.force = force.values().back(); }

void SpringMass::eventFunctions(const SpringMassState& s, devs::Time, std::span<double> g) const {
  g[0] = s.x;
}

void SpringMass::outputAt(const SpringMassState& s, devs::Time, const dtss::Reached& r) const {
  if (r.stateEvent == 0) upcrossing.add(s.v);
}

namespace {
StepMethod method(const std::string& name) {
  if (name == "euler") return StepMethod::Euler;
  if (name == "symplectic_euler") return StepMethod::SymplecticEuler;
  return StepMethod::Rk4;
}
}  // namespace

YARDSIM_REGISTER_TYPE(spring_mass, TypeInfo{
    .name = "spring_mass",
    .summary = "mass on a linear spring and damper, stepped at dt (DTSS); input `force` in N",
    .params =
        {
            {"mass", ParamKind::Number, true, "", "kg", "mass"},
            {"stiffness", ParamKind::Number, true, "", "N/m", "spring stiffness"},
            {"damping", ParamKind::Number, false, "0", "N*s/m", "viscous damping"},
            {"x0", ParamKind::Number, false, "0", "m", "initial displacement"},
            {"v0", ParamKind::Number, false, "0", "m/s", "initial velocity"},
            {"dt", ParamKind::Number, true, "", "s", "step"},
            {"method", ParamKind::String, false, "rk4", "", "euler, symplectic_euler or rk4"},
            {"blowup_limit", ParamKind::Number, false, "1e6", "m",
             "|x| beyond this stops the run as a numerical failure"},
        },
    .ports = [](const Params&) {
      return std::vector<PortSpec>{{"force", "double", true, true}, {"upcrossing", "double", false}};
    },
    .create = [](const std::string& n, const Params& p) -> std::unique_ptr<devs::AtomicBase> {
      return std::make_unique<SpringMass>(
          n, SpringMassParams{p.number("mass"), p.number("stiffness"), p.number("damping"),
                              p.number("x0"), p.number("v0"), p.number("dt"),
                              method(p.string("method")), p.number("blowup_limit")});
    },
    .check =
        [](const Params& p, ParamCheck& c) {
          if (!(p.number("mass") > 0)) c.error("mass", "must be > 0 kg");
          if (!(p.number("stiffness") > 0)) c.error("stiffness", "must be > 0 N/m");
          if (p.number("damping") < 0) c.error("damping", "must be >= 0 N*s/m");
          if (!(p.number("dt") > 0)) c.error("dt", "must be > 0 s");
          const auto m = p.string("method");
          if (m != "euler" && m != "symplectic_euler" && m != "rk4")
            c.error("method", "expected euler, symplectic_euler or rk4, got '" + m + "'");
        },
    .feedthrough = {}});

}  // namespace yardsim::models::library
