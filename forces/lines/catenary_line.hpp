#pragma once
// A quasi-static catenary mooring line (forces/lines/catenary.hpp) as a force provider: its
// anchor is a point on the ground or on a body, its fairlead a point on a body. At every stage
// the spans follow from the world points, x horizontal from the anchor toward the fairlead
// (unit vector e_h), z up (the world z axis): XF = |horizontal part of p_B - p_A|,
// ZF = (p_B - p_A).z; the Newton solve is warm-started from the last evaluate() with the same
// scratch (the caller's, one per system: a temporary one starts cold). The fairlead
// feels F_B = -HF e_h - VF e_z and the anchor body F_A = HA e_h + VA e_z (world frame, N, at the
// points); F_A + F_B differs from zero by the line's weight and the sea bed's reaction.
// Linearised (forces/provider_linearisation.hpp) about p_A0, p_B0 with K = fairleadStiffness():
// F_B = F_B0 - K (d - d_0), F_A = F_A0 + K (d - d_0), d = p_B - p_A (the forces depend on d only;
// with the anchor on the ground p_A is fixed).
// Potential energy: the line's stored energy (weight and strain) plus w L z_A, J (zero at the
// world's z = 0, like Gravity). Power: 0 without sea-bed friction (the line is conservative);
// with friction the quasi-static model is not, and power() reports F . v + dV/dt (the friction's
// quasi-static work rate, W) with dV/dt by a central difference along the motion, so the energy
// balance closes. A fairlead within 1e-9 L horizontally of its anchor is evaluated at 1e-9 L in
// the last horizontal direction. Conventions: docs/forces.md.
#include <string>
#include <vector>

#include "forces/force_provider.hpp"
#include "forces/lines/catenary.hpp"
#include "forces/provider_linearisation.hpp"
#include "forces/rope_path.hpp"

namespace yardsim::forces {

// The line at one stage: the solution, the spans (m), e_h, and the forces on the two ends
// (world frame, N).
struct CatenaryLineState {
  CatenarySolution solution;
  double xf = 0.0, zf = 0.0;
  dynamics::Vector3 horizontal = dynamics::Vector3::UnitX();
  dynamics::Vector3 fairleadForce = dynamics::Vector3::Zero();
  dynamics::Vector3 anchorForce = dynamics::Vector3::Zero();
};

class CatenaryLine final : public ForceProvider, public ProviderLinearisation {
 public:
  // (name, model (checks only), anchor, fairlead (on a body >= 1), parameters) => the line;
  // throws std::invalid_argument naming it for a body outside the model, a fairlead on the
  // ground, a non-finite point, bad parameters (catenaryParameterError) or a sea bed with the
  // anchor on a body. With parameters.seabed the sea bed is the horizontal plane through the
  // anchor. With the anchor on a body (no sea bed) the ends' 6x6 stiffness is [K -K; -K K].
  CatenaryLine(std::string name, const dynamics::Model& model, const Attachment& anchor,
               const Attachment& fairlead, const CatenaryParameters& parameters);

  // (stage) => the line there (warm-started from the last evaluate() with the stage's scratch,
  // which it does not change);
  // throws ForceError naming the line when the solve fails (no convergence, fairlead below the
  // sea bed)
  CatenaryLineState state(const Stage& s) const;
  // (stage) => K = -dF_B/dp_B, the fairlead's 3x3 stiffness in the world frame, N/m (symmetric
  // without friction)
  dynamics::Matrix3 fairleadStiffness(const Stage& s) const;
  // (stage, segments n >= 1) => the line's shape: n + 1 world points (m) at the unstretched arc
  // lengths k L / n from the anchor (k = 0) to the fairlead (k = n), in the vertical plane through
  // the ends (on the bed where it lies there); throws ForceError as state()
  std::vector<dynamics::Vector3> profile(const Stage& s, int segments) const;
  const CatenaryParameters& parameters() const { return p_; }
  const Attachment& anchor() const { return anchor_; }
  const Attachment& fairlead() const { return fairlead_; }

  // (stage with the scratch) => the linearisation about it in the scratch (one solve, warm
  // start kept); (scratch) => evaluate() solves again
  void linearise(const Stage& s) const override;
  void release(ProviderScratch& scratch) const override;

  // the scratch: the last evaluate()'s solution and horizontal direction (the warm start), and
  // the linearisation while one is in force: its base span vector d_0 (m), end forces (N) and K
  struct Scratch final : ProviderScratch {
    CatenarySolution last;
    dynamics::Vector3 lastHorizontal = dynamics::Vector3::UnitX();
    bool linearised = false;
    dynamics::Vector3 span0 = dynamics::Vector3::Zero();
    dynamics::Vector3 fairleadForce0 = dynamics::Vector3::Zero();
    dynamics::Vector3 anchorForce0 = dynamics::Vector3::Zero();
    dynamics::Matrix3 stiffness0 = dynamics::Matrix3::Zero();
    // (warm start) => HF, VF, e_h: all that the next solve starts from
    void carried(std::vector<double>& out) const override {
      out.insert(out.end(),
                 {last.hf, last.vf, lastHorizontal.x(), lastHorizontal.y(), lastHorizontal.z()});
    }
    void restoreCarried(std::span<const double> v) override {
      if (v.size() != 5) return;
      last.hf = v[0];
      last.vf = v[1];
      lastHorizontal = dynamics::Vector3(v[2], v[3], v[4]);
    }
  };
  std::unique_ptr<ProviderScratch> makeScratch() const override;

 protected:
  void doEvaluate(const Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd& tau) const override;
  double doPotentialEnergy(const Stage& s) const override;
  double doPower(const Stage& s) const override;

 private:
  // (state) => K = -dF_B/dp_B there (world frame, N/m)
  static dynamics::Matrix3 stiffnessOf(const CatenaryLineState& st);
  // (anchor and fairlead world points, warm start) => the state
  CatenaryLineState solveAt(const dynamics::Vector3& pA, const dynamics::Vector3& pB,
                            const Scratch& warm, double t) const;
  // (stage) => its scratch, or a cold one
  const Scratch& warmStart(const Stage& s) const {
    static const Scratch cold;
    return s.scratch != nullptr ? static_cast<const Scratch&>(*s.scratch) : cold;
  }

  Attachment anchor_, fairlead_;
  CatenaryParameters p_;
};

}  // namespace yardsim::forces
