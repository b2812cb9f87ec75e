// The `bushings:` key of a `mechanics:` block (docs/scenes.md): 6-dof bushings between a frame on
// one body and a frame on another (forces/bushing.hpp), with their channels fx..mz.
#include <Eigen/Eigenvalues>

#include "forces/bushing.hpp"
#include "forces/provider_outputs.hpp"
#include "scene/providers/reader_support.hpp"

namespace yardsim::scene::providers {

namespace {

using dynamics::Matrix6;
using dynamics::Vector3;
using mechanics::MechanicsSpec;

// (entry, key of a 6-list or 6x6 list in the order x, y, z, rx, ry, rz) => the matrix in the
// bushing's order [angular; linear] (zero when absent)
Matrix6 readMatrix(const spec::Reader& r, const YAML::Node& n, const std::string& key) {
  Matrix6 yaml = Matrix6::Zero();
  if (!n) return yaml;
  if (n.IsSequence() && n.size() == 6 && n[0].IsSequence()) {
    for (int i = 0; i < 6; ++i) {
      const auto row = r.numbers(n[i], key + "[" + std::to_string(i) + "]", 6);
      for (int j = 0; j < 6; ++j) yaml(i, j) = row[static_cast<std::size_t>(j)];
    }
  } else {
    const auto d = r.numbers(n, key, 6);
    for (int i = 0; i < 6; ++i) yaml(i, i) = d[static_cast<std::size_t>(i)];
  }
  // (x, y, z, rx, ry, rz) => (rx, ry, rz, x, y, z)
  Eigen::Matrix<double, 6, 6> P = Matrix6::Zero();
  for (int i = 0; i < 3; ++i) {
    P(i, i + 3) = 1.0;
    P(i + 3, i) = 1.0;
  }
  return P * yaml * P.transpose();
}

// (attachments: origin, origin + x axis, origin + y axis of a frame, placed) => the frame
dynamics::Transform frameFrom(const forces::Attachment& o, const forces::Attachment& x,
                              const forces::Attachment& y) {
  const Vector3 ex = (x.p_B - o.p_B).normalized();
  const Vector3 ey = ((y.p_B - o.p_B) - ex.dot(y.p_B - o.p_B) * ex).normalized();
  dynamics::Matrix3 R;
  R.col(0) = ex;
  R.col(1) = ey;
  R.col(2) = ex.cross(ey);
  return {R, o.p_B};
}

// (entry {body_a, frame_a, body_b, frame_b, stiffness, damping}) => a Bushing with the channels
// fx, fy, fz (N) and mx, my, mz (N m): its generalized force Q in frame F (B feels -Q)
MechanicsSpec::ProviderSpec readBushing(const std::string&, const YAML::Node& n,
                                        const spec::Reader& r, const std::string& key) {
  MechanicsSpec::ProviderSpec out;
  r.keys(n, {"body_a", "frame_a", "body_b", "frame_b", "stiffness", "damping"}, key);
  if (!n.IsMap()) return out;
  // (each frame) => three points on its body that the fragment's placement moves like the frame
  for (const char* end : {"a", "b"}) {
    const std::string b = std::string("body_") + end, f = std::string("frame_") + end;
    const std::string body = n[b] ? bodyName(r, n, b.c_str(), key + "." + b) : "world";
    const dynamics::Transform X = r.pose(n[f], key + "." + f);
    for (const Vector3& p : {Vector3(0, 0, 0), Vector3(1, 0, 0), Vector3(0, 1, 0)})
      out.attachments.push_back({body, X.p + X.R * p});
  }
  if (out.attachments[0].first == out.attachments[3].first)
    r.fail(n, key, "a bushing connects two different bodies (body_a, body_b; default world)");
  if (!n["stiffness"] && !n["damping"])
    r.fail(n, key, "missing 'stiffness' and 'damping' (a 6-list or 6x6, x, y, z, rx, ry, rz)");
  forces::BushingProperties p;
  p.stiffness = readMatrix(r, n["stiffness"], key + ".stiffness");
  p.damping = readMatrix(r, n["damping"], key + ".damping");
  const auto symmetric = [](const Matrix6& m) {
    return (m - m.transpose()).norm() <= 1e-12 * m.norm();
  };
  if (!symmetric(p.stiffness)) r.fail(n["stiffness"], key + ".stiffness", "must be symmetric");
  if (!symmetric(p.damping))
    r.fail(n["damping"], key + ".damping", "must be symmetric");
  else if (Eigen::SelfAdjointEigenSolver<Matrix6>(p.damping).eigenvalues().minCoeff() <
           -1e-12 * p.damping.norm())
    r.fail(n["damping"], key + ".damping", "must be positive semidefinite (it dissipates)");
  // (name, the system's model, the attachments placed) => the provider with its channels
  out.build = [p](const std::string& name, const dynamics::Model& model,
                  const std::vector<forces::Attachment>& at) {
    const dynamics::Transform X_AF = frameFrom(at.at(0), at.at(1), at.at(2));
    const dynamics::Transform X_BG = frameFrom(at.at(3), at.at(4), at.at(5));
    auto bushing =
        std::make_unique<forces::Bushing>(name, model, at[0].body, X_AF, at[3].body, X_BG, p);
    return forces::withOutputs<forces::Bushing>(std::move(bushing), [](const forces::Bushing& b) {
      std::vector<forces::ProviderOutput> o;
      const char* names[6] = {"mx", "my", "mz", "fx", "fy", "fz"};
      for (int k : {3, 4, 5, 0, 1, 2})
        o.push_back({names[k], k < 3 ? "N m" : "N",
                     [&b, k](const forces::Stage& s) { return b.state(s).generalizedForce[k]; }});
      return o;
    });
  };
  return out;
}

}  // namespace

YARDSIM_REGISTER_PROVIDER(bushings,
                          ProviderReader{
                              .key = "bushings",
                              .summary = "name: {body_a, frame_a: {xyz, rpy_deg}, body_b, frame_b, "
                                         "stiffness, damping (6 or 6x6, x y z rx ry rz)}",
                              .read = readBushing});

}  // namespace yardsim::scene::providers
