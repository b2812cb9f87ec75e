#pragma once
// One mechanically connected system at run time (DESIGN.md, mechanics/): the built mechanics
// (the immutable dynamics::Model, q0, v0, names, rope and load specs, the environment), the one
// list of force providers built from them in evaluation order (ropes: the wire ropes, then the
// equalizers; hydrostatics, wind and current loads, damping, body loads from time series, the
// added mass following a draft (its momentum force), the providers of registered readers), the
// watched quantities and the joint servos' settings. Built once; the stage function (stage.hpp),
// the energy balance (energy.hpp), the event table (events.hpp), the blow-up checks (blowup.hpp)
// and the stiffness estimate all iterate the same list. Providers are const while they are
// evaluated (their scratch is in mechanics::Data); the winches (the ropes', and those of crane
// ropes with mass) take payout set-points between steps, so a System serves one run at a time.
#include <memory>
#include <string>
#include <vector>

#include "forces/body_load.hpp"
#include "forces/flow_load.hpp"
#include "forces/hydro/draft_added_mass.hpp"
#include "forces/hydrostatics.hpp"
#include "forces/linear_quadratic_damping.hpp"
#include "forces/lines/lumped_line_provider.hpp"
#include "forces/provider_events.hpp"
#include "forces/rope.hpp"
#include "mechanics/description.hpp"

namespace yardsim::mechanics {

// The joint servos (docs/scenes.md): bandwidth rad/s (0: min(10, 0.1/dt)), force bound N m or N
// (0: unbounded), and the tolerance rad or m within which a drive has reached its target.
struct ServoSettings {
  double bandwidth = 0.0;
  double maxEffort = 0.0;
  double tolerance = 1e-3;
};

// A watched quantity, resolved: what it reads and which dof, body or rope.
struct WatchRef {
  enum class Kind { Q, V, Position, Angle, Tension, Length } kind;
  int index, axis;
};

// A winch actors drive (a wire actor's payout), by the name of the rope it belongs to: a massless
// rope's (forces::Rope::winch()) or a provider's (ForceProvider::payoutWinch(): a crane rope with
// mass). The winch is mutable between steps, like the rope's set-points.
struct WinchRef {
  std::string name;
  forces::Winch* winch;
};

class System {
 public:
  // (built mechanics, servo settings with bandwidth resolved) => every provider built; throws
  // std::invalid_argument naming what is wrong (a watch on an unknown quantity, a load without
  // its environment)
  System(BuiltMechanics mechanics, const ServoSettings& servo, const std::string& name);
  System(const System&) = delete;
  System& operator=(const System&) = delete;

  const dynamics::Model& model() const { return mech_.model; }
  const BuiltMechanics& description() const { return mech_; }
  const ServoSettings& servo() const { return servo_; }
  // the one list, in evaluation order
  const std::vector<forces::ForceProvider*>& providers() const { return providers_; }
  // typed views of the same providers, for channels, events and replay; ropes: the wire ropes
  // of description().ropes, then the equalizers of description().equalizers
  const std::vector<std::unique_ptr<forces::Rope>>& ropes() const { return ropes_; }
  const std::vector<std::unique_ptr<forces::Hydrostatics>>& hydrostatics() const { return hydros_; }
  const std::vector<std::unique_ptr<forces::FlowLoad>>& flows() const { return flows_; }
  const std::vector<std::unique_ptr<forces::LinearQuadraticDamping>>& dampers() const {
    return dampers_;
  }
  const std::vector<std::unique_ptr<forces::BodyLoad>>& bodyLoads() const { return bodyLoads_; }
  // the providers of registered readers (MechanicsSpec::ProviderSpec), last in the list
  const std::vector<std::unique_ptr<forces::ForceProvider>>& contributed() const {
    return contributed_;
  }
  // the bodies whose added mass follows their draft (mechanics/follow_draft.hpp)
  const std::vector<std::unique_ptr<forces::hydro::DraftAddedMass>>& draftAddedMass() const {
    return draftAddedMass_;
  }
  // the lumped lines under a winch (crane ropes with mass): their inner nodes' mass follows the
  // rope paid out (mechanics/follow_mass.hpp)
  const std::vector<const forces::LumpedLineProvider*>& winchedLines() const {
    return winchedLines_;
  }
  const std::vector<WatchRef>& watches() const { return watchRefs_; }
  // the located state events the contributed providers declare (forces/provider_events.hpp)
  const std::vector<const forces::ProviderEvent*>& providerEvents() const {
    return providerEvents_;
  }
  // per body: the joint-space inertia of its 1-dof joint at q0 (kg m^2 or kg), for servo gains
  const std::vector<double>& servoInertia() const { return servoInertia_; }

  // the winches: every rope's (index r of ropes() is winch r), then the providers' with one
  const std::vector<WinchRef>& winches() const { return winches_; }

  // (joint name) => body index, or -1; (rope name) => rope index, or -1; (rope name) => winch
  // index, or -1
  int jointBody(const std::string& joint) const;
  int ropeIndex(const std::string& rope) const;
  int winchIndex(const std::string& rope) const;

 private:
  BuiltMechanics mech_;
  ServoSettings servo_;
  std::vector<std::unique_ptr<forces::Rope>> ropes_;
  std::vector<std::unique_ptr<forces::Hydrostatics>> hydros_;
  std::vector<std::unique_ptr<forces::FlowLoad>> flows_;
  std::vector<std::unique_ptr<forces::LinearQuadraticDamping>> dampers_;
  std::vector<std::unique_ptr<forces::BodyLoad>> bodyLoads_;
  std::vector<std::unique_ptr<forces::ForceProvider>> contributed_;
  std::vector<std::unique_ptr<forces::hydro::DraftAddedMass>> draftAddedMass_;
  std::vector<forces::ForceProvider*> providers_;
  std::vector<const forces::LumpedLineProvider*> winchedLines_;
  std::vector<WatchRef> watchRefs_;
  std::vector<const forces::ProviderEvent*> providerEvents_;
  std::vector<WinchRef> winches_;
  std::vector<double> servoInertia_;
};

}  // namespace yardsim::mechanics
