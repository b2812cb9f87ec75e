#pragma once
// A steel wire rope between attachment points on bodies or the ground, as one type for every
// reeving (docs/forces.md):
//  - a wire rope: one branch (its first end, frictionless sheaves, its last end) reeved in n
//    parts between its end blocks; the end blocks feel n T;
//  - an equalizer: k >= 2 branches from one common equalizing sheave point to their own ends,
//    one part each; the rope slides freely over the equalizing sheave, so the branches share one
//    unstretched length L0 and one tension T (the load-balancing device of shipyard cranes).
// One law (rope_law.hpp) on the total length L = sum over branches of L_j against L0(t) of one
// part: tension-only, viscous damping while taut, stiffness EA/L0. One winch (winch.hpp)
// changes L0 at set rates. Tension T is per part, N; lengths m; rates m/s; times s.
#include <memory>
#include <string>
#include <vector>

#include "forces/force_provider.hpp"
#include "forces/rope_law.hpp"
#include "forces/rope_path.hpp"
#include "forces/winch.hpp"

namespace yardsim::forces {

class Rope final : public ForceProvider {
 public:
  // (name, model (for checks only), path: first end, sheaves..., last end, material of one
  // part, number of parts n >= 1) => a wire rope at rest; properties.l0 is the unstretched
  // length of one part. Throws std::invalid_argument naming the rope when a parameter is out
  // of range or not finite.
  Rope(std::string name, const dynamics::Model& model, std::vector<Attachment> path,
       const RopeProperties& properties, int parts = 1);
  // (name, model (for checks only), the equalizing sheave point, per branch its points after
  // the sheave (sheaves..., end attachment), material with properties.l0 the unstretched length
  // of all branches together) => an equalizer at rest; throws std::invalid_argument naming it
  // for fewer than 2 branches, an empty branch or a parameter out of range.
  Rope(std::string name, const dynamics::Model& model, const Attachment& sheave,
       const std::vector<std::vector<Attachment>>& branches, const RopeProperties& properties);

  // (t, rate) => from time t on the unstretched length L0 (one part; an equalizer: all its
  // branches) changes at rate, m/s (> 0 pays out; with n parts the drum speed is n rate); L0
  // never goes below properties.minLength. Set-points come in time order.
  void setPayoutRate(double t, double rate) { winch_.setPayoutRate(t, rate); }
  // (t) => L0(t), m; and its rate, m/s
  double unstretchedLength(double t) const { return winch_.length(t); }
  double payoutRate(double t) const { return winch_.rate(t); }
  // the winch itself (its history, for checkpoints)
  const Winch& winch() const { return winch_; }
  Winch& winch() { return winch_; }

  // (stage) => tension of one part T >= 0, N
  double tension(const Stage& s) const;
  // (stage) => stretched length L = sum of the branches' lengths (one part), m; its rate, m/s
  double length(const Stage& s) const { return measure(s).length; }
  double lengthRate(const Stage& s) const { return measure(s).rate; }
  // (stage, branch j) => the length of branch j, m
  double branchLength(const Stage& s, int j) const { return branches_[j].measure(s.data).length; }
  // (stage) => the rope is longer than L0(t)
  bool isTaut(const Stage& s) const { return length(s) > unstretchedLength(s.t); }
  // (stage) => its tension exceeds the minimum breaking load (never if none was given)
  bool exceedsBreakingLoad(const Stage& s) const {
    return properties_.breakingLoad && tension(s) > *properties_.breakingLoad;
  }

  int parts() const { return parts_; }
  const RopeProperties& properties() const { return properties_; }
  // "wire rope" or "equalizer", for messages
  const std::string& kind() const { return kind_; }
  int branchCount() const { return static_cast<int>(branches_.size()); }
  // branch j's path (an equalizer's starts at the sheave point); path() is the first
  const RopePath& branch(int j) const { return branches_[j]; }
  const RopePath& path() const { return branches_.front(); }

  // the scratch: every branch's world points at the stage
  struct Scratch final : ProviderScratch {
    std::vector<PathPoints> branches;
  };
  std::unique_ptr<ProviderScratch> makeScratch() const override;

 protected:
  void doEvaluate(const Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd& tau) const override;
  // n EA/(2 L0) (L - L0)^2 while taut, J
  double doPotentialEnergy(const Stage& s) const override;
  // damping and clamping -n (T - T_elastic) dL/dt plus the winch's n dV/dL0 dL0/dt, W
  double doPower(const Stage& s) const override;

 private:
  // (stage) => sum of the branches' lengths and rates
  PathMeasure measure(const Stage& s) const;
  // (stage, path measure) => strain state of one part at s.t
  RopeStrain strain(const Stage& s, const PathMeasure& m) const;

  std::string kind_;
  RopeProperties properties_;
  int parts_;
  std::vector<RopePath> branches_;
  Winch winch_;
};

}  // namespace yardsim::forces
