#pragma once
// A lumped-mass line (lumped_line.hpp) as a force provider whose inner nodes are part of the
// integrated state. Each inner node i = 1 .. N-1 is a body of the multibody tree: a point mass on
// a translation joint from the world whose joint frame is the world frame, so its q is the node's
// position p_W (m) and its v the node's velocity (m/s, world). Every integrator (explicit,
// implicit, SUNDIALS) then steps the nodes with the other bodies, the stiffness guard sees their
// axial modes in its linearisation, and a checkpoint of the multibody state holds them. Node 0 is
// the anchor point and node N the fairlead point, each on the ground or on a body: their
// positions and velocities follow those bodies and their node forces (their half segments'
// weight, drag and bed included) act on those bodies at the points.
//
// Per inner node the provider adds to its joint's generalized force (= the world force on the
// node) the line's node force minus the model's gravity on the node's mass m_i: the model applies
// m_i g to every body; the line's net weight w l_n (buoyancy included) replaces it. The node mass
// is mu l_n + rho V Can: a body's mass in the model is isotropic, so the added mass is taken
// isotropic with the normal coefficient (the tangential one, usually smaller, is not used for the
// mass; docs/lines.md). Potential energy: the line's (strain, bending, net weight, bed springs)
// plus sum m_i g_model . r_i, which cancels the model's own gravity potential of the nodes.
// Power: the part of the node forces that is not -dV/dr (internal and bed damping, friction,
// drag, the flow's inertia force) times the node velocities, plus dV/dt, the power of the line's
// winch when it has one (a crane rope's: payoutWinch() takes its set-points between steps, the
// line's unstretched length follows it, lumped_line.hpp).
// Under a winch an inner node's mass follows the rope paid out: m_i(t) = m_i l(t)/l (m_i the
// model's, built at the start's segment length l), nodeMass(i, t). The model keeps m_i; the
// difference m_i(t) - m_i is what mechanics writes into the kernels' added mass before they run
// (mechanics/follow_mass.hpp; gravity does not act on it, so the weight stays w l_n(t)). The
// rope that leaves a node (hauled in) or joins it (paid out) does so at the node's velocity: no
// force, m_i(t) dv_i/dt = f_i, and the kinetic energy it takes or brings, 1/2 m_i'(t) |v_i|^2,
// is in the power (docs/lines.md, "A winch on a rope between two points"). World frame, SI units.
#include <memory>
#include <string>
#include <vector>

#include "forces/force_provider.hpp"
#include "forces/lines/lumped_line.hpp"
#include "forces/rope_path.hpp"

namespace yardsim::forces {

// An inner node as a body of the tree: its name, mass (kg) and position at the start (world, m).
struct LumpedNodeBody {
  std::string name;
  double mass = 0.0;
  dynamics::Vector3 p_W = dynamics::Vector3::Zero();
};

// (line's name, node index) => "<line>.node<i>", the name of that node's body
std::string lumpedNodeName(const std::string& line, int i);

// (line, its name, anchor and fairlead world points at the start) => the inner nodes' bodies at
// the chain's static equilibrium (lumped_line_statics.hpp) found from the elastic catenary through
// the two ends (catenary.hpp, with the line's sea bed when the anchor lies on it), or from the
// straight chord when there is no catenary; at the guess itself when Newton fails
std::vector<LumpedNodeBody> lumpedLineNodes(const LumpedLine& line, const std::string& name,
                                            const dynamics::Vector3& pA,
                                            const dynamics::Vector3& pB);

class LumpedLineProvider final : public ForceProvider {
 public:
  // (name, model holding the bodies lumpedNodeName(name, 1 .. N-1) on translation joints from the
  // world with the identity joint placement, anchor, fairlead, the line) => the provider; throws
  // std::invalid_argument naming it for a missing or wrong node body or a point outside the model
  // A winch, when given, must be the line's own (line->winch()): the provider hands it out.
  LumpedLineProvider(std::string name, const dynamics::Model& model, const Attachment& anchor,
                     const Attachment& fairlead, std::shared_ptr<const LumpedLine> line,
                     std::shared_ptr<Winch> winch = nullptr);
  // () => the line's winch, for set-points between steps; null without one
  Winch* payoutWinch() override { return winch_.get(); }

  // the scratch: node positions, velocities and forces (3 x (N+1)), segment tensions (N)
  struct Scratch final : ProviderScratch {
    Eigen::Matrix3Xd r, v, f, fc;
    Eigen::VectorXd tension;
  };
  std::unique_ptr<ProviderScratch> makeScratch() const override;

  // (stage) => every node's position and velocity (world) in w.r and w.v
  void gather(const Stage& s, Scratch& w) const;
  // (stage) => the force of the line on the fairlead, |f_N| (its last segment and half-segment
  // weight, drag and bed), and the tension of the first segment at the anchor, N
  double fairleadTension(const Stage& s) const;
  double anchorTension(const Stage& s) const;
  // (stage) => the horizontal part of the line's force on the fairlead, |f_N| in the world's
  // horizontal plane (x, y), N: the catenary's HF
  double horizontalTension(const Stage& s) const;
  // (stage) => unstretched length of the nodes on the sea bed (0 without one), m: the nodes
  // within one diameter of it (onBed)
  double laidLength(const Stage& s) const;
  // (stage) => the angle below the horizontal of the line's force on the fairlead, f_N (> 0: the
  // line runs down from the fairlead), rad: atan2(-f_N.z, |f_N horizontal|), the catenary's
  // atan2(VF, HF)
  double fairleadAngle(const Stage& s) const;
  // (stage) => the angle above the horizontal of the line's force on the anchor, f_0 (> 0: it
  // lifts the anchor), rad, the catenary's atan2(VA, HA); with a sea bed its vertical part is
  // max(0, f_0.z): a line lying on the bed at the anchor does not pull it down (the bed carries
  // the anchor node's half segment, which the node model hangs on the anchor)
  double anchorAngle(const Stage& s) const;
  // The touchdown point: the last node of the run of nodes from the anchor that lie on the bed
  // (onBed; the anchor itself for a suspended line or without a bed), its horizontal distance
  // from the anchor (m) and its world position (m).
  struct Touchdown {
    double distance = 0.0;
    dynamics::Vector3 point = dynamics::Vector3::Zero();
  };
  // (stage) => the touchdown point, within about a segment of the continuous line's
  Touchdown touchdown(const Stage& s) const;
  // (node positions, node) => true when the node lies on the sea bed: a bed, and the node within
  // one diameter above it (or below it)
  bool onBed(const Eigen::Matrix3Xd& r, int i) const {
    const LumpedLineProperties& p = line_->properties();
    return p.seabed && r(2, i) <= p.seabedZ + p.diameter;
  }
  // (stage) => per inner node i the blocks d a_i/d r_j (1/s^2) and d a_i/d v_j (1/s) of its
  // acceleration a_i = f_i / m_i(t) (a point mass on its own joint) for j = i - b .. i + b at
  // [(2 b + 1) i + j - i + b], b = line().jacobianBandwidth() (1, or 2 with bending)
  // (LumpedLine::forceJacobian over the node's mass; the end nodes' rows are the force's, N/m
  // and N s/m), both sized (2 b + 1) (N + 1); returns the line's switch signature.
  // Allocation-free.
  std::uint64_t accelerationJacobian(const Stage& s, std::vector<dynamics::Matrix3>& dadr,
                                     std::vector<dynamics::Matrix3>& dadv) const;

  const LumpedLine& line() const { return *line_; }
  const Attachment& anchor() const { return anchor_; }
  const Attachment& fairlead() const { return fairlead_; }
  // (inner node i in 1 .. N-1) => its body index
  int nodeBody(int i) const { return bodies_[static_cast<std::size_t>(i)]; }
  // (inner node i in 1 .. N-1, t) => its mass at t, m_i l(t)/l, kg (the model's without a winch
  // or at the start's length), and its rate m_i l'(t)/l, kg/s
  double nodeMass(int i, double t) const {
    return masses_[static_cast<std::size_t>(i)] *
           (line_->segmentLength(t) / line_->segmentLength());
  }
  double nodeMassRate(int i, double t) const {
    return masses_[static_cast<std::size_t>(i)] *
           (line_->segmentLengthRate(t) / line_->segmentLength());
  }

 protected:
  void doEvaluate(const Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd& tau) const override;
  double doPotentialEnergy(const Stage& s) const override;
  double doPower(const Stage& s) const override;

 private:
  // (stage) => the scratch evaluated there: nodes gathered, node forces and tensions
  Scratch& evaluated(const Stage& s, std::unique_ptr<ProviderScratch>& temporary) const;

  Attachment anchor_, fairlead_;
  std::shared_ptr<const LumpedLine> line_;
  std::shared_ptr<Winch> winch_;
  dynamics::Vector3 gravity_;  // the model's, m/s^2
  std::vector<int> bodies_;    // per node: its body (inner nodes), -1 at the ends
  std::vector<int> idxQ_, idxV_;
  std::vector<double> masses_;  // per node: the body's mass (inner nodes), kg
};

}  // namespace yardsim::forces
