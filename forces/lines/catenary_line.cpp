#include "forces/lines/catenary_line.hpp"

#include <cmath>
#include <stdexcept>

#include "dynamics/kinematics.hpp"

namespace yardsim::forces {

using dynamics::Matrix3;
using dynamics::Vector3;

namespace {
// (model, point, which, owner) => the point, checked
const Attachment& checkedPoint(const dynamics::Model& model, const Attachment& a, const char* which,
                               const std::string& owner) {
  if (a.body < 0 || a.body >= model.nbodies)
    throw std::invalid_argument("catenary line '" + owner + "': the " + which + " is on body " +
                                std::to_string(a.body) + ", outside the model's " +
                                std::to_string(model.nbodies) + " bodies");
  if (!a.p_B.allFinite())
    throw std::invalid_argument("catenary line '" + owner + "': the " + which + " is not finite");
  return a;
}
// (parameters, owner) => the parameters, checked
const CatenaryParameters& checked(const CatenaryParameters& p, const std::string& owner) {
  const std::string e = catenaryParameterError(p);
  if (!e.empty()) throw std::invalid_argument("catenary line '" + owner + "': " + e);
  return p;
}
const char* statusText(CatenaryStatus s) {
  switch (s) {
    case CatenaryStatus::NoConvergence:
      return "the catenary solve did not converge";
    case CatenaryStatus::BelowSeabed:
      return "the fairlead is below the sea bed";
    case CatenaryStatus::BadInput:
      return "the spans are not finite";
    case CatenaryStatus::Converged:
      break;
  }
  return "";
}
}  // namespace

CatenaryLine::CatenaryLine(std::string name, const dynamics::Model& model, const Attachment& anchor,
                           const Attachment& fairlead, const CatenaryParameters& parameters)
    : ForceProvider(std::move(name)),
      anchor_(checkedPoint(model, anchor, "anchor", this->name())),
      fairlead_(checkedPoint(model, fairlead, "fairlead", this->name())),
      p_(checked(parameters, this->name())) {
  if (fairlead_.body == 0)
    throw std::invalid_argument("catenary line '" + this->name() +
                                "': the fairlead must be on a body, not the ground");
  if (p_.seabed && anchor_.body != 0)
    throw std::invalid_argument("catenary line '" + this->name() +
                                "': a line resting on the sea bed needs its anchor on the ground");
}

std::unique_ptr<ProviderScratch> CatenaryLine::makeScratch() const {
  return std::make_unique<Scratch>();
}

CatenaryLineState CatenaryLine::solveAt(const Vector3& pA, const Vector3& pB, const Scratch& warm,
                                        double t) const {
  const CatenarySolution& guess = warm.last;
  // (p_A, p_B) => spans, e_h, the Newton solve warm-started from guess, the end forces
  CatenaryLineState st;
  const Vector3 d = pB - pA;
  const double xh = std::hypot(d.x(), d.y()), minX = 1e-9 * p_.length;
  st.horizontal = xh > minX ? Vector3(d.x() / xh, d.y() / xh, 0.0) : warm.lastHorizontal;
  st.xf = std::max(xh, minX);
  st.zf = d.z();
  st.solution = solveCatenary(p_, st.xf, st.zf, guess.hf, guess.vf);
  if (st.solution.status != CatenaryStatus::Converged)
    throw ForceError("catenary line '" + name() + "' at t = " + std::to_string(t) + ": " +
                     statusText(st.solution.status) + " (XF = " + std::to_string(st.xf) +
                     " m, ZF = " + std::to_string(st.zf) + " m)");
  const CatenarySolution& c = st.solution;
  st.fairleadForce = -c.hf * st.horizontal - c.vf * Vector3::UnitZ();
  st.anchorForce = c.ha * st.horizontal + c.va * Vector3::UnitZ();
  return st;
}

CatenaryLineState CatenaryLine::state(const Stage& s) const {
  return solveAt(dynamics::pointPosition(s.data, anchor_.body, anchor_.p_B),
                 dynamics::pointPosition(s.data, fairlead_.body, fairlead_.p_B), warmStart(s),
                 s.t);
}

std::vector<Vector3> CatenaryLine::profile(const Stage& s, int segments) const {
  // (the solution at the stage) => its points at equal unstretched arc lengths, in the world
  const CatenaryLineState st = state(s);
  const Vector3 pA = dynamics::pointPosition(s.data, anchor_.body, anchor_.p_B);
  std::vector<Vector3> out;
  for (int k = 0; k <= segments; ++k) {
    const CatenaryPoint c = catenaryPoint(p_, st.solution, st.xf, p_.length * k / segments);
    out.push_back(pA + c.x * st.horizontal + c.z * Vector3::UnitZ());
  }
  return out;
}

Matrix3 CatenaryLine::fairleadStiffness(const Stage& s) const {
  return stiffnessOf(state(s));
}

Matrix3 CatenaryLine::stiffnessOf(const CatenaryLineState& st) {
  // (J^-1, e_h, HF/XF) => K = e_h (k11 e_h + k12 e_z)^T + HF/XF (I_h - e_h e_h^T)
  //                           + e_z (k21 e_h + k22 e_z)^T
  const CatenarySolution& c = st.solution;
  const Vector3& e = st.horizontal;
  const Vector3 z = Vector3::UnitZ();
  Matrix3 Ih = Matrix3::Identity();
  Ih(2, 2) = 0.0;
  return e * (c.k11 * e + c.k12 * z).transpose() + c.hf / st.xf * (Ih - e * e.transpose()) +
         z * (c.k21 * e + c.k22 * z).transpose();
}

void CatenaryLine::linearise(const Stage& s) const {
  // (the stage's solve, its stiffness) => the base of F_B0 - K (d - d_0), F_A0 + K (d - d_0)
  if (s.scratch == nullptr) return;
  auto& lin = static_cast<Scratch&>(*s.scratch);
  const Vector3 pA = dynamics::pointPosition(s.data, anchor_.body, anchor_.p_B);
  const Vector3 pB = dynamics::pointPosition(s.data, fairlead_.body, fairlead_.p_B);
  lin.linearised = false;
  const CatenaryLineState st = solveAt(pA, pB, lin, s.t);
  lin.span0 = pB - pA;
  lin.fairleadForce0 = st.fairleadForce;
  lin.anchorForce0 = st.anchorForce;
  lin.stiffness0 = stiffnessOf(st);
  lin.linearised = true;
}

void CatenaryLine::release(ProviderScratch& scratch) const {
  static_cast<Scratch&>(scratch).linearised = false;
}

void CatenaryLine::doEvaluate(const Stage& s, dynamics::ExternalForces& f,
                              Eigen::VectorXd& /*tau*/) const {
  const Vector3 pA = dynamics::pointPosition(s.data, anchor_.body, anchor_.p_B);
  const Vector3 pB = dynamics::pointPosition(s.data, fairlead_.body, fairlead_.p_B);
  if (s.scratch != nullptr && static_cast<const Scratch&>(*s.scratch).linearised) {
    // (linearised: a Jacobian's difference) => the forces' linearisation, no solve, warm start kept
    const auto& lin = static_cast<const Scratch&>(*s.scratch);
    const Vector3 dF = lin.stiffness0 * (pB - pA - lin.span0);
    f.addPointForceWorld(fairlead_.body, pB, lin.fairleadForce0 - dF);
    if (anchor_.body != 0) f.addPointForceWorld(anchor_.body, pA, lin.anchorForce0 + dF);
    return;
  }
  const CatenaryLineState st = solveAt(pA, pB, warmStart(s), s.t);
  if (s.scratch != nullptr) {  // (the caller's scratch) => the next stage starts from here
    auto& warm = static_cast<Scratch&>(*s.scratch);
    warm.last = st.solution;
    warm.lastHorizontal = st.horizontal;
  }
  f.addPointForceWorld(fairlead_.body, pB, st.fairleadForce);
  if (anchor_.body != 0) f.addPointForceWorld(anchor_.body, pA, st.anchorForce);
}

double CatenaryLine::doPotentialEnergy(const Stage& s) const {
  const Vector3 pA = dynamics::pointPosition(s.data, anchor_.body, anchor_.p_B);
  const CatenaryLineState st = state(s);
  return catenaryEnergy(p_, st.solution) + p_.weight * p_.length * pA.z();
}

double CatenaryLine::doPower(const Stage& s) const {
  // (no friction, or nothing on the bed) => conservative; else F . v + dV/dt with dV/dt by a
  // central difference of the stored energy along the ends' motion (a step of 1e-6 L)
  if (p_.friction == 0.0 || !p_.seabed) return 0.0;
  const Vector3 pA = dynamics::pointPosition(s.data, anchor_.body, anchor_.p_B);
  const Vector3 pB = dynamics::pointPosition(s.data, fairlead_.body, fairlead_.p_B);
  const Vector3 vA = dynamics::pointVelocity(s.data, anchor_.body, anchor_.p_B);
  const Vector3 vB = dynamics::pointVelocity(s.data, fairlead_.body, fairlead_.p_B);
  const CatenaryLineState st = solveAt(pA, pB, warmStart(s), s.t);
  const CatenaryProfile prof = st.solution.profile;
  if (prof != CatenaryProfile::TouchingDown && prof != CatenaryProfile::OnSeabed) return 0.0;
  const double speed = vA.norm() + vB.norm();
  if (!(speed > 0.0)) return 0.0;
  const double h = 1e-6 * p_.length / speed;
  Scratch here;
  here.last = st.solution;
  here.lastHorizontal = st.horizontal;
  const CatenaryLineState up = solveAt(pA + h * vA, pB + h * vB, here, s.t);
  const CatenaryLineState down = solveAt(pA - h * vA, pB - h * vB, here, s.t);
  const double dVdt =
      (catenaryEnergy(p_, up.solution) - catenaryEnergy(p_, down.solution)) / (2.0 * h) +
      p_.weight * p_.length * vA.z();
  return st.fairleadForce.dot(vB) + st.anchorForce.dot(vA) + dVdt;
}

}  // namespace yardsim::forces
