#pragma once
// Compliant contact as a force provider: at every integrator stage a source (a callable given by
// the layer that owns the geometry: the collision kernel through mechanics/, or an analytic
// ground) lists the stage's contact points; the provider applies the contact law
// (contact_law.hpp) to each and adds the forces to the two bodies. Knows nothing of FCL.
//
// Per point: bodies A and B (0 = the world), p_W the contact point (m, world), n_W the unit
// normal from A towards B, depth >= 0 (m). The relative velocity of B's material point at p_W
// with respect to A's, v = v_B - v_A (m/s, world), gives the depth rate delta_dot = -v . n and
// the slip v_t = v - (v . n) n. B receives F = F_n n + F_t at p_W, A receives -F at the same
// point. Potential energy: the sum of the penalty springs' energies; power: the law's
// dissipation (damping, the no-pull clamp, friction), <= 0.
#include <functional>
#include <string>
#include <vector>

#include "forces/contact_law.hpp"
#include "forces/force_provider.hpp"

namespace yardsim::forces {

struct ContactPoint {
  int bodyA = 0;
  int bodyB = 0;
  dynamics::Vector3 p_W = dynamics::Vector3::Zero();   // m
  dynamics::Vector3 n_W = dynamics::Vector3::UnitZ();  // unit, from A towards B
  double depth = 0.0;                                  // m, >= 0
  int material = 0;  // index into the provider's materials (one material: 0)
};

// The law of one material pair: normal law and friction.
struct ContactMaterial {
  NormalLaw law;
  FrictionLaw friction;
};

// (stage, out: cleared by the provider) => the stage's contact points appended to out
using ContactSource = std::function<void(const Stage&, std::vector<ContactPoint>&)>;

class ContactForce final : public ForceProvider {
 public:
  // (name, source, normal law, friction, points to reserve room for) => the provider; throws
  // std::invalid_argument for an empty source, a negative stiffness or damping, a friction
  // coefficient < 0 or a slip speed <= 0
  ContactForce(std::string name, ContactSource source, NormalLaw law, FrictionLaw friction,
               std::size_t reserve = 64);
  // (name, source, one law per material pair: a point's `material` indexes it, reserve) => the
  // provider; the same checks for every material, and a non-empty list
  ContactForce(std::string name, ContactSource source, std::vector<ContactMaterial> materials,
               std::size_t reserve = 64);

  const std::vector<ContactMaterial>& materials() const { return materials_; }

  // the scratch: the stage's points and the response at each (reserved: no allocation in the
  // loop); after evaluate() with a scratch, what it applied (channels, replay)
  struct Scratch final : ProviderScratch {
    std::vector<ContactPoint> points;
    std::vector<ContactResponse> responses;
  };
  std::unique_ptr<ProviderScratch> makeScratch() const override;
  // a contact closes and opens: its regime is the set of points pressing (F_n > 0)
  bool switches() const override { return true; }

 protected:
  void doEvaluate(const Stage& s, dynamics::ExternalForces& f,
                  Eigen::VectorXd& tau) const override;
  double doPotentialEnergy(const Stage& s) const override;
  double doPower(const Stage& s) const override;
  // (stage) => the number of points pressing and the body pairs they join, as one signature
  std::uint64_t doRegime(const Stage& s) const override;

 private:
  // (stage) => the scratch's points from the source and responses from the law
  void collect(const Stage& s, Scratch& out) const;

  ContactSource source_;
  std::vector<ContactMaterial> materials_;
  std::size_t reserve_;
};

}  // namespace yardsim::forces
