#pragma once
// A lumped-mass rope (lumped_line.hpp) over one frictionless sheave: a crane rope with mass from
// a first end over a sheave point to a last end, each on a body or the ground. It is three pieces
// of existing code: span A, a lumped line (LumpedLineProvider) from the first end to its node p;
// the segment over the sheave, a massless rope (forces::Rope) from p over the sheave point S to q,
// one unstretched segment length l whose tension is the same on both sides of S (the rope law of
// rope_law.hpp with EA/l and the lumped segments' damping); span B, a lumped line from q to the
// last end. Every segment has the same unstretched length l = L0 / n. p and q are point-mass
// bodies on translation joints from the world, like the spans' inner nodes, each of mass mu l
// (half of its span's end segment and half of the sheave's); the provider replaces the model's
// gravity on them by the half segment over the sheave's net weight (the span's half is in the
// span's end force). So rope flows over the sheave only within that one segment: the material
// coordinate at the sheave moves by at most about l / 2 either way (the segment over the sheave
// grows on one side as it shrinks on the other); a rope that runs farther over its sheave (a
// hoist paying out) needs the massless rope. World frame, SI units.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "forces/force_provider.hpp"
#include "forces/lines/lumped_line_provider.hpp"
#include "forces/rope.hpp"

namespace yardsim::forces {

// (segments n >= 3, first end, sheave point and last end at the start, world) => the segments of
// span A (span B has n - 1 - n_A): in proportion to the straight distances from the sheave, each
// span at least 1
int firstSpanSegments(int n, const dynamics::Vector3& a, const dynamics::Vector3& s,
                      const dynamics::Vector3& b);

// (rope's name) => the bodies of p and q: "<rope>.a.node<n_A>" (the last node of span A
// "<rope>.a") and "<rope>.b.node0" (the first of span B "<rope>.b")
std::string sheaveNodeName(const std::string& rope, bool first, int spanASegments);

class LumpedRopeOverSheave final : public ForceProvider {
 public:
  // (name, model holding the spans' node bodies and p and q, the first end, the sheave point and
  // the last end, the spans' lines (their segment lengths equal: l), the sheave segment's EA (N)
  // and damping (N s/m)) => the rope; throws std::invalid_argument naming it for a missing body
  LumpedRopeOverSheave(std::string name, const dynamics::Model& model, const Attachment& first,
                       const Attachment& sheave, const Attachment& last,
                       std::shared_ptr<const LumpedLine> spanA,
                       std::shared_ptr<const LumpedLine> spanB, double damping);

  // the spans' and the sheave segment's scratches
  struct Scratch final : ProviderScratch {
    std::unique_ptr<ProviderScratch> a, b, sheave;
  };
  std::unique_ptr<ProviderScratch> makeScratch() const override;

  const LumpedLineProvider& spanA() const { return *spanA_; }
  const LumpedLineProvider& spanB() const { return *spanB_; }
  const Rope& overSheave() const { return *sheave_; }
  // (stage) => the tension of the segment over the sheave, N (the same on both sides of it)
  double sheaveTension(const Stage& s) const;

 protected:
  void doEvaluate(const Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd& tau) const override;
  double doPotentialEnergy(const Stage& s) const override;
  double doPower(const Stage& s) const override;

 private:
  // (stage, its scratch) => the stage for span A (0), span B (1) or the sheave segment (2)
  static Stage sub(const Stage& s, Scratch& w, int piece);

  std::unique_ptr<LumpedLineProvider> spanA_, spanB_;
  std::unique_ptr<Rope> sheave_;
  std::array<int, 2> pq_{};       // the bodies of p and q
  std::array<double, 2> mass_{};  // their masses, kg
  double halfWeight_ = 0.0;       // w l / 2, N: the half segment over the sheave's net weight
  dynamics::Vector3 gravity_;     // the model's, m/s^2
};

}  // namespace yardsim::forces
