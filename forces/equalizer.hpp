#pragma once
// An equalizer: k >= 2 rope branches that run from one common equalizing sheave point (on a
// body or the ground) to their own attachments, optionally over sheaves. The rope slides freely
// over the equalizing sheave, so the branches share one unstretched length L0 and one tension
// T, and the load is balanced between them whatever their geometry (the load-balancing device
// of shipyard cranes). Law: the wire rope's (rope_law.hpp) on the total length L = sum L_j;
// the sheave body feels T sum u_j. Conventions and the energy balance: docs/forces.md.
#include <string>
#include <vector>

#include "forces/force_provider.hpp"
#include "forces/rope_law.hpp"
#include "forces/rope_path.hpp"
#include "forces/winch.hpp"

namespace yardsim::forces {

class Equalizer final : public ForceProvider {
 public:
  // (name, model (for checks only), the equalizing sheave point, per branch its points after
  // the sheave (sheaves..., end attachment), material with properties.l0 the unstretched length
  // of all branches together) => an equalizer at rest; throws std::invalid_argument naming it
  // for fewer than 2 branches, an empty branch or a parameter out of range.
  Equalizer(std::string name, const dynamics::Model& model, const Attachment& sheave,
            const std::vector<std::vector<Attachment>>& branches, const RopeProperties& properties);

  // (t, rate) => from t on the total unstretched length changes at rate, m/s (see Winch)
  void setPayoutRate(double t, double rate) { winch_.setPayoutRate(t, rate); }
  double unstretchedLength(double t) const { return winch_.length(t); }
  double payoutRate(double t) const { return winch_.rate(t); }

  // (stage) => the common tension T of every branch, N
  double tension(const Stage& s) const;
  // (stage) => total stretched length sum L_j, m; its rate, m/s
  double length(const Stage& s) const { return measure(s).length; }
  double lengthRate(const Stage& s) const { return measure(s).rate; }
  // (stage, branch j) => length of branch j from the sheave point, m
  double branchLength(const Stage& s, int j) const { return branches_[j].measure(s.data).length; }
  bool isTaut(const Stage& s) const { return length(s) > unstretchedLength(s.t); }

  // (stage) => its tension exceeds the minimum breaking load (never if none was given)
  bool exceedsBreakingLoad(const Stage& s) const {
    return properties_.breakingLoad && tension(s) > *properties_.breakingLoad;
  }

  int branchCount() const { return static_cast<int>(branches_.size()); }
  // branch j's path, starting at the sheave point
  const RopePath& branch(int j) const { return branches_[j]; }
  const RopeProperties& properties() const { return properties_; }

  // the scratch: every branch's world points at the stage
  struct Scratch final : ProviderScratch {
    std::vector<PathPoints> branches;
  };
  std::unique_ptr<ProviderScratch> makeScratch() const override;

 protected:
  void doEvaluate(const Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd& tau) const override;
  double doPotentialEnergy(const Stage& s) const override;
  double doPower(const Stage& s) const override;

 private:
  // (stage) => sum of the branches' lengths and rates
  PathMeasure measure(const Stage& s) const;
  RopeStrain strain(const Stage& s, const PathMeasure& m) const;

  RopeProperties properties_;
  std::vector<RopePath> branches_;
  Winch winch_;
};

}  // namespace yardsim::forces
