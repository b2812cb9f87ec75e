#include "forces/lines/lumped_line.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "forces/lines/lumped_line_bending.hpp"

namespace yardsim::forces {

using dynamics::Matrix3;
using dynamics::Vector3;

namespace {
// (properties, name) => properties, checked
const LumpedLineProperties& checked(const LumpedLineProperties& p, const std::string& name) {
  auto bad = [&](const std::string& what) {
    throw std::invalid_argument("lumped line '" + name + "': " + what);
  };
  auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  auto nonNegative = [](double x) { return std::isfinite(x) && x >= 0.0; };
  if (!positive(p.length) || !positive(p.diameter) || !positive(p.massPerLength) || !positive(p.ea))
    bad("length, diameter, mass per length and EA must be finite and > 0");
  if (!nonNegative(p.ei)) bad("the bending stiffness EI must be finite and >= 0");
  if (p.segments < 1) bad("it needs at least one segment");
  if (!std::isfinite(p.damping)) bad("the damping must be finite");
  if (!nonNegative(p.cdn) || !nonNegative(p.cdt) || !nonNegative(p.can) || !nonNegative(p.cat))
    bad("drag and added-mass coefficients must be finite and >= 0");
  if (!positive(p.waterDensity) || !positive(p.gravity))
    bad("water density and gravity must be > 0");
  if (!std::isfinite(p.seabedZ) || !nonNegative(p.bedStiffness) || !nonNegative(p.bedDamping) ||
      !nonNegative(p.bedFriction) || !positive(p.frictionSpeed))
    bad("sea-bed parameters must be finite and >= 0 (friction speed > 0)");
  return p;
}
}  // namespace

LumpedLine::LumpedLine(const LumpedLineProperties& p, std::string name, const AiryWaves* waves,
                       const CurrentField* current, std::shared_ptr<const Winch> winch)
    : p_(checked(p, name)),
      name_(std::move(name)),
      waves_(waves),
      current_(current),
      winch_(std::move(winch)) {
  if (winch_ && winch_->history().front().l0 != p_.length)
    throw std::invalid_argument("lumped line '" + name_ + "': its winch starts at " +
                                std::to_string(winch_->history().front().l0) +
                                " m, not at the line's length " + std::to_string(p_.length) + " m");
  if (winch_ && !(winch_->minLength() > 0.0))
    throw std::invalid_argument("lumped line '" + name_ +
                                "': its winch's minimum length must be > 0 (the nodes' masses "
                                "follow the length paid out)");
  l_ = p_.length / p_.segments;
  area_ = 0.25 * std::numbers::pi * p_.diameter * p_.diameter;
  w_ = (p_.massPerLength - p_.waterDensity * area_) * p_.gravity;
  // (a segment's axial mode: reduced mass mu l/4, stiffness EA/l) => critical c = l sqrt(EA mu)
  c_ = p_.damping >= 0.0 ? p_.damping : -p_.damping * l_ * std::sqrt(p_.ea * p_.massPerLength);
}

Vector3 LumpedLine::tangent(const Eigen::Matrix3Xd& r, int i) const {
  const int n = p_.segments;
  const Vector3 d = r.col(std::min(i + 1, n)) - r.col(std::max(i - 1, 0));
  const double len = d.norm();
  return len > 0.0 ? Vector3(d / len) : Vector3::UnitZ();
}

void LumpedLine::nodeForces(const Eigen::Matrix3Xd& r, const Eigen::Matrix3Xd& v, double t,
                            Eigen::Matrix3Xd& f, Eigen::VectorXd& tension) const {
  const int n = p_.segments;
  const double rho = p_.waterDensity;
  const double l = segmentLength(t), lr = segmentLengthRate(t);
  // (segments) => tension-only Kelvin-Voigt forces, +T u on node i, -T u on node i + 1
  f.setZero();
  for (int i = 0; i < n; ++i) {
    const Vector3 d = r.col(i + 1) - r.col(i);
    const double len = d.norm();
    const double strain = len / l - 1.0;
    double T = 0.0;
    if (strain > 0.0) {
      const Vector3 u = d / len;
      double rate = u.dot(v.col(i + 1) - v.col(i)) / l;
      if (lr != 0.0) rate -= len * lr / (l * l);  // (a winch) => e' = u.dv / l - |d| l' / l^2
      T = std::max(0.0, p_.ea * strain + c_ * rate);
      f.col(i) += T * u;
      f.col(i + 1) -= T * u;
    }
    tension[i] = T;
  }
  // (EI > 0) => the bending's node forces
  if (p_.ei > 0.0) addBendingForces(r, p_.ei / l, f);
  // (nodes) => weight, Morison drag and fluid inertia, sea bed
  for (int i = 0; i <= n; ++i) {
    const Vector3 p = r.col(i), vi = v.col(i);
    const double ln = nodeLength(i, l);
    const double ls = 0.5 * ((i > 0 ? (r.col(i) - r.col(i - 1)).norm() : 0.0) +
                             (i < n ? (r.col(i + 1) - r.col(i)).norm() : 0.0));
    Vector3 fi(0.0, 0.0, -w_ * ln);
    const Vector3 q = tangent(r, i);
    Vector3 uf = current_ ? current_->velocity(p) : Vector3::Zero();
    if (waves_) uf += waves_->velocity(p, t);
    const Vector3 vr = uf - vi;
    const Vector3 vt = vr.dot(q) * q, vn = vr - vt;
    fi += 0.5 * rho * p_.diameter * ls *
          (p_.cdn * vn.norm() * vn + p_.cdt * std::numbers::pi * vt.norm() * vt);
    if (waves_) {
      const Vector3 a = waves_->acceleration(p, t);
      const Vector3 at = a.dot(q) * q;
      fi += rho * area_ * ln * ((1.0 + p_.can) * (a - at) + (1.0 + p_.cat) * at);
    }
    if (p_.seabed && p.z() < p_.seabedZ) {
      const double dl = p_.diameter * ln;
      const double normal =
          std::max(0.0, (p_.seabedZ - p.z()) * p_.bedStiffness * dl - vi.z() * p_.bedDamping * dl);
      fi.z() += normal;
      const Vector3 vh(vi.x(), vi.y(), 0.0);
      const double speed = vh.norm();
      if (speed > 0.0 && p_.bedFriction > 0.0)
        fi -= p_.bedFriction * normal * std::min(1.0, speed / p_.frictionSpeed) / speed * vh;
    }
    f.col(i) += fi;
  }
}

void LumpedLine::nodeMass(const Eigen::Matrix3Xd& r, double t, std::vector<Matrix3>& m) const {
  // (q, l_n(t)) => mu l_n I + rho V [Can (I - q q^T) + Cat q q^T], V = A l_n
  const double l = segmentLength(t);
  for (int i = 0; i <= p_.segments; ++i) {
    const double ln = nodeLength(i, l);
    const Vector3 q = tangent(r, i);
    const Matrix3 qq = q * q.transpose();
    m[static_cast<std::size_t>(i)] =
        p_.massPerLength * ln * Matrix3::Identity() +
        p_.waterDensity * area_ * ln * (p_.can * (Matrix3::Identity() - qq) + p_.cat * qq);
  }
}

double LumpedLine::potentialEnergy(const Eigen::Matrix3Xd& r, double t) const {
  const double l = segmentLength(t);
  double e = 0.0;
  for (int i = 0; i < p_.segments; ++i) {
    const double strain = (r.col(i + 1) - r.col(i)).norm() / l - 1.0;
    if (strain > 0.0) e += 0.5 * p_.ea * l * strain * strain;
  }
  if (p_.ei > 0.0) e += bendingEnergy(r, p_.ei / l);
  for (int i = 0; i <= p_.segments; ++i) {
    const double ln = nodeLength(i, l), z = r(2, i);
    e += w_ * ln * z;
    if (p_.seabed && z < p_.seabedZ)
      e += 0.5 * p_.bedStiffness * p_.diameter * ln * (p_.seabedZ - z) * (p_.seabedZ - z);
  }
  return e;
}

double LumpedLine::potentialEnergyRate(const Eigen::Matrix3Xd& r, double t) const {
  const double lr = segmentLengthRate(t);
  if (lr == 0.0) return 0.0;
  // (V = sum EA l e^2 / 2 + EI/l B + sum w l_n z + sum kb d l_n (z_bed - z)^2 / 2, e = |d|/l - 1,
  // l_n proportional to l) => dV/dl = sum -EA e (1 + e/2) - EI/l B / l + (the l_n terms) / l
  const double l = segmentLength(t);
  double dVdl = 0.0;
  for (int i = 0; i < p_.segments; ++i) {
    const double strain = (r.col(i + 1) - r.col(i)).norm() / l - 1.0;
    if (strain > 0.0) dVdl -= p_.ea * strain * (1.0 + 0.5 * strain);
  }
  if (p_.ei > 0.0) dVdl -= bendingEnergy(r, p_.ei / l) / l;
  for (int i = 0; i <= p_.segments; ++i) {
    const double ln = nodeLength(i, l), z = r(2, i);
    double e = w_ * ln * z;
    if (p_.seabed && z < p_.seabedZ)
      e += 0.5 * p_.bedStiffness * p_.diameter * ln * (p_.seabedZ - z) * (p_.seabedZ - z);
    dVdl += e / l;
  }
  return dVdl * lr;
}

void LumpedLine::conservativeForces(const Eigen::Matrix3Xd& r, double t,
                                    Eigen::Matrix3Xd& f) const {
  // (segments, weight, bed springs) => -dV/dr, the elastic parts of nodeForces without rates
  const int n = p_.segments;
  const double l = segmentLength(t);
  f.setZero();
  for (int i = 0; i < n; ++i) {
    const Vector3 d = r.col(i + 1) - r.col(i);
    const double len = d.norm();
    const double strain = len / l - 1.0;
    if (strain > 0.0) {
      const Vector3 pull = p_.ea * strain / len * d;
      f.col(i) += pull;
      f.col(i + 1) -= pull;
    }
  }
  if (p_.ei > 0.0) addBendingForces(r, p_.ei / l, f);
  for (int i = 0; i <= n; ++i) {
    const double ln = nodeLength(i, l), z = r(2, i);
    f(2, i) -= w_ * ln;
    if (p_.seabed && z < p_.seabedZ)
      f(2, i) += (p_.seabedZ - z) * p_.bedStiffness * p_.diameter * ln;
  }
}

namespace {
// (x) => d(|x| x)/dx = |x| I + x x^T / |x| (zero at x = 0)
Matrix3 quadraticGradient(const Vector3& x) {
  const double n = x.norm();
  return n > 0.0 ? Matrix3(n * Matrix3::Identity() + x * x.transpose() / n) : Matrix3::Zero();
}
}  // namespace

std::uint64_t LumpedLine::forceJacobian(const Eigen::Matrix3Xd& r, const Eigen::Matrix3Xd& v,
                                        double t, std::vector<Matrix3>& dfdr,
                                        std::vector<Matrix3>& dfdv) const {
  const int n = p_.segments;
  const double rho = p_.waterDensity;
  const double l = segmentLength(t), lr = segmentLengthRate(t);
  for (std::size_t k = 0; k < dfdr.size(); ++k) {
    dfdr[k].setZero();
    dfdv[k].setZero();
  }
  std::uint64_t signature = 1469598103934665603ull;  // FNV-1a over the switches
  auto mix = [&](bool on) { signature = (signature ^ (on ? 1u : 2u)) * 1099511628211ull; };
  const int b = jacobianBandwidth();
  auto at = [b](int node, int other) {
    return static_cast<std::size_t>((2 * b + 1) * node + other - node + b);
  };
  // (taut segment, d = r_(i+1) - r_i, u = d/|d|, P = I - u u^T) => d(T u)/dd = EA/l u u^T
  // + T/|d| P + c/(l |d|) u (P dv)^T (- c l'/l^2 u u^T under a winch) and d(T u)/d(dv) =
  // c/l u u^T; T u acts on i, -T u on i + 1
  for (int i = 0; i < n; ++i) {
    const Vector3 d = r.col(i + 1) - r.col(i);
    const double len = d.norm();
    bool taut = false;
    if (len > l) {
      const Vector3 u = d / len, dv = v.col(i + 1) - v.col(i);
      double T = p_.ea * (len / l - 1.0) + c_ * u.dot(dv) / l;
      if (lr != 0.0) T -= c_ * len * lr / (l * l);
      if (T > 0.0) {
        taut = true;
        const Matrix3 uu = u * u.transpose(), P = Matrix3::Identity() - uu;
        Matrix3 K = (p_.ea / l) * uu + (T / len) * P + (c_ / (l * len)) * u * (P * dv).transpose();
        if (lr != 0.0) K -= (c_ * lr / (l * l)) * uu;
        const Matrix3 C = (c_ / l) * uu;
        dfdr[at(i, i + 1)] += K;
        dfdr[at(i, i)] -= K;
        dfdr[at(i + 1, i + 1)] -= K;
        dfdr[at(i + 1, i)] += K;
        dfdv[at(i, i + 1)] += C;
        dfdv[at(i, i)] -= C;
        dfdv[at(i + 1, i + 1)] -= C;
        dfdv[at(i + 1, i)] += C;
      }
    }
    mix(taut);
  }
  // (EI > 0) => the bending energy's Hessian, blocks within two nodes
  if (p_.ei > 0.0)
    bendingJacobian(r, p_.ei / l, [&](int i, int j, const Matrix3& K) { dfdr[at(i, j)] += K; });
  // (nodes) => drag on the relative velocity vr = u_f - v: -(kn G(vn) (I - q q^T) + kt G(vt) q q^T)
  for (int i = 0; i <= n; ++i) {
    const Vector3 p = r.col(i), vi = v.col(i);
    Matrix3& kr = dfdr[at(i, i)];
    Matrix3& kv = dfdv[at(i, i)];
    if (p_.cdn > 0.0 || p_.cdt > 0.0) {
      const double ls = 0.5 * ((i > 0 ? (r.col(i) - r.col(i - 1)).norm() : 0.0) +
                               (i < n ? (r.col(i + 1) - r.col(i)).norm() : 0.0));
      const Vector3 q = tangent(r, i);
      Vector3 uf = current_ ? current_->velocity(p) : Vector3::Zero();
      if (waves_) uf += waves_->velocity(p, t);
      const Vector3 vr = uf - vi;
      const Vector3 vt = vr.dot(q) * q, vn = vr - vt;
      const Matrix3 qq = q * q.transpose();
      const double k = 0.5 * rho * p_.diameter * ls;
      kv -= k * (p_.cdn * quadraticGradient(vn) * (Matrix3::Identity() - qq) +
                 p_.cdt * std::numbers::pi * quadraticGradient(vt) * qq);
    }
    // (below the bed, pressing) => N = (z_bed - z) kb d l_n - vz cb d l_n; friction -mu N g vh
    // with g = min(1, s/s0)/s on the horizontal velocity vh, s = |vh|
    bool onBed = false, sliding = false;
    if (p_.seabed && p.z() < p_.seabedZ) {
      const double dl = p_.diameter * nodeLength(i, l);
      const double normal =
          (p_.seabedZ - p.z()) * p_.bedStiffness * dl - vi.z() * p_.bedDamping * dl;
      if (normal > 0.0) {
        onBed = true;
        const double dNdz = -p_.bedStiffness * dl, dNdvz = -p_.bedDamping * dl;
        kr(2, 2) += dNdz;
        kv(2, 2) += dNdvz;
        if (p_.bedFriction > 0.0) {
          const Vector3 vh(vi.x(), vi.y(), 0.0);
          const double s = vh.norm();
          sliding = s >= p_.frictionSpeed;
          const double g = sliding ? 1.0 / s : 1.0 / p_.frictionSpeed;
          const double mu = p_.bedFriction;
          kr.col(2) -= mu * g * dNdz * vh;
          kv.col(2) -= mu * g * dNdvz * vh;
          Matrix3 Ih = Matrix3::Zero();
          Ih(0, 0) = Ih(1, 1) = 1.0;
          kv -= mu * normal * g * (sliding ? Matrix3(Ih - vh * vh.transpose() / (s * s)) : Ih);
        }
      }
    }
    mix(onBed);
    mix(sliding);
  }
  return signature;
}

}  // namespace yardsim::forces
