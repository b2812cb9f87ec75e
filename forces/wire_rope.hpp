#pragma once
// A steel wire rope between two attachment points (on bodies or the ground), optionally over
// frictionless sheaves, reeved in n parts (falls) between its end blocks. Tension-only with
// viscous damping while taut, stiffness EA/L0 from the current unstretched length L0, which a
// winch changes at a set rate. The per-part tension T is reported; the end blocks feel n T.
// Conventions and the energy balance: docs/forces.md.
#include <string>
#include <vector>

#include "forces/force_provider.hpp"
#include "forces/rope_law.hpp"
#include "forces/rope_path.hpp"
#include "forces/winch.hpp"

namespace yardsim::forces {

class WireRope final : public ForceProvider {
 public:
  // (name, model (for checks only), path: first end, sheaves..., last end, material of one
  // part, number of parts n >= 1) => a rope at rest; throws std::invalid_argument naming the
  // rope when a parameter is out of range or not finite. properties.l0 is the unstretched
  // length of one part between the first and last path points.
  WireRope(std::string name, const dynamics::Model& model, std::vector<Attachment> path,
           const RopeProperties& properties, int parts = 1);

  // (t, rate) => from time t on the unstretched length of a part changes at rate, m/s (> 0 pays
  // out and lowers the load by rate; with n parts the drum speed is n rate); L0 never goes
  // below properties.minLength. Set-points come in time order (std::invalid_argument otherwise).
  void setPayoutRate(double t, double rate) { winch_.setPayoutRate(t, rate); }
  // (t) => unstretched length of one part L0(t), m; and its rate, m/s
  double unstretchedLength(double t) const { return winch_.length(t); }
  double payoutRate(double t) const { return winch_.rate(t); }
  // the winch itself (its history, for checkpoints)
  const Winch& winch() const { return winch_; }
  Winch& winch() { return winch_; }

  // (stage) => tension of one part T >= 0, N; the end blocks feel n T
  double tension(const Stage& s) const;
  // (stage) => stretched length of the path (one part), m; and its rate, m/s
  double length(const Stage& s) const { return path_.measure(s.data).length; }
  double lengthRate(const Stage& s) const { return path_.measure(s.data).rate; }
  // (stage) => the path is longer than L0(t)
  bool isTaut(const Stage& s) const { return length(s) > unstretchedLength(s.t); }

  // (stage) => its tension exceeds the minimum breaking load (never if none was given)
  bool exceedsBreakingLoad(const Stage& s) const {
    return properties_.breakingLoad && tension(s) > *properties_.breakingLoad;
  }

  int parts() const { return parts_; }
  const RopeProperties& properties() const { return properties_; }
  // the path (its world points at a stage: path().update(data, points))
  const RopePath& path() const { return path_; }

  // the scratch: the path's world points at the stage
  struct Scratch final : ProviderScratch {
    PathPoints points;
  };
  std::unique_ptr<ProviderScratch> makeScratch() const override;

 protected:
  void doEvaluate(const Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd& tau) const override;
  // n EA/(2 L0) (L - L0)^2 while taut, J
  double doPotentialEnergy(const Stage& s) const override;
  // damping and clamping -n (T - T_elastic) dL/dt plus the winch's n dV/dL0 dL0/dt, W
  double doPower(const Stage& s) const override;

 private:
  // (stage, path measure) => strain state of one part at s.t
  RopeStrain strain(const Stage& s, const PathMeasure& m) const;

  RopeProperties properties_;
  int parts_;
  RopePath path_;
  Winch winch_;
};

}  // namespace yardsim::forces
