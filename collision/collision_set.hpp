#pragma once
// One collision set of a mechanical system as a force provider: the contact forces of its
// bodies (forces::ContactForce on the points of a BodyCollision), with channels and located
// events. Outputs (forces/provider_outputs.hpp), each `<set>.<output>`:
//   points [-]            contact points at the state
//   normal_force [N]      the sum of their normal forces
//   <body>.fz [N]         the vertical (world z) component of the contact forces on each body
//   <body>.px|py|pz [m]   where the normal forces on each body act (their force-weighted mean
//                         point, world), NaN without contact
//   <watch>.distance [m]  each clearance watch's minimum distance (its range when farther)
// Events (forces/provider_events.hpp):
//   <set>: contact / release   the first contact point appears / the last one goes (g: the
//                              deepest penetration, signed where the ground gives a distance)
//   <set>.<watch>: clearance_below   the watch's distance falls below its threshold
//   <set>.<watch>: touched           the distance reaches 0
// with the pair's names and witness points (m, world) as the detail of a watch's events.
// Stiffness (forces/provider_stiffness.hpp): what the contacts bring in once a body rests on them.
#include <memory>
#include <string>
#include <vector>

#include "collision/body_collision.hpp"
#include "forces/contact.hpp"
#include "forces/provider_events.hpp"
#include "forces/provider_outputs.hpp"
#include "forces/provider_stiffness.hpp"

namespace yardsim::collision {

class CollisionSet final : public forces::ForceProvider,
                           public forces::ProviderOutputs,
                           public forces::ProviderEvents,
                           public forces::ProviderStiffness {
 public:
  struct Options {
    // false: only the clearance watches (no points, normal_force, fz, contact/release)
    bool contact = true;
    // true: each watch's channel is `<watch>.distance` and its events' element `<watch>` (the
    // scene-level form); false: `<set>.<watch>.distance` and `<set>.<watch>`
    bool watchesAtTop = false;
  };
  // (name, the world of the set's bodies, one contact law per material pair, the names of the
  // bodies whose fz is a channel with their indices, options) => the provider
  CollisionSet(std::string name, std::shared_ptr<BodyCollision> world,
               std::vector<forces::ContactMaterial> materials,
               const std::vector<std::pair<std::string, int>>& reactionBodies, Options options);
  CollisionSet(std::string name, std::shared_ptr<BodyCollision> world,
               std::vector<forces::ContactMaterial> materials,
               const std::vector<std::pair<std::string, int>>& reactionBodies)
      : CollisionSet(std::move(name), std::move(world), std::move(materials), reactionBodies,
                     Options{}) {}

  const std::vector<forces::ProviderOutput>& outputs() const override { return outputs_; }
  const std::vector<forces::ProviderEvent>& events() const override { return events_; }
  std::unique_ptr<forces::ProviderScratch> makeScratch() const override {
    return contact_->makeScratch();
  }
  const forces::ContactForce& contact() const { return *contact_; }
  // contacts close and open (not a set of watches only): the implicit methods sub-step a step
  // that changes which points press (forces/force_provider.hpp, regime)
  bool switches() const override { return options_.contact; }
  // (model) => the highest frequency of a body resting on its contacts under its weight: the
  // normal law's sqrt(k_eff / m) (k_eff = N k, Hunt-Crossley N n k delta^(n-1) at the static
  // depth, N = 4 points for a box, mesh or cylinder, 1 for a sphere or capsule) and friction's
  // viscous rate mu g / v_s (the regularised stick), over the set's bodies that can move and
  // its laws
  forces::StiffnessHint stiffnessHint(const dynamics::Model& model) const override;

 protected:
  void doEvaluate(const forces::Stage& s, dynamics::ExternalForces& f,
                  Eigen::VectorXd& tau) const override {
    contact_->evaluate(s, f, tau);
  }
  double doPotentialEnergy(const forces::Stage& s) const override {
    return contact_->potentialEnergy(s);
  }
  double doPower(const forces::Stage& s) const override { return contact_->power(s); }
  std::uint64_t doRegime(const forces::Stage& s) const override { return contact_->regime(s); }

 private:
  // (stage) => the contact points and the law's responses at it, in the stage's scratch or, for
  // a stage without one (the event function, a one-off read), in unowned_
  const forces::ContactForce::Scratch& collected(const forces::Stage& s) const;
  // (bodies whose fz is a channel) => points, normal_force, <body>.fz, contact/release
  void addContactOutputs(const std::vector<std::pair<std::string, int>>& reactionBodies);
  // (stage) => the deepest penetration of the set, > 0 in contact
  double penetration(const forces::Stage& s) const;

  std::shared_ptr<BodyCollision> world_;
  std::unique_ptr<forces::ContactForce> contact_;
  // the scratch of the reads given none, made once: rewritten by every such read, so that the
  // event function evaluated at every step allocates nothing (not thread-safe, as world_)
  std::unique_ptr<forces::ProviderScratch> unowned_;
  std::vector<forces::ProviderOutput> outputs_;
  std::vector<forces::ProviderEvent> events_;
  Options options_;
};

}  // namespace yardsim::collision
