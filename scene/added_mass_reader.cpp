#include "scene/added_mass_reader.hpp"

#include <cmath>
#include <filesystem>
#include <vector>

#include "dynamics/added_mass.hpp"
#include "dynamics/data.hpp"
#include "dynamics/kinematics.hpp"
#include "forces/geometry/mesh_io.hpp"
#include "forces/hydro/added_mass.hpp"

namespace yardsim::scene {

using mechanics::MechanicsSpec;

namespace {

// (matrix node) => 6x6 in the naval order, or nothing after a report
std::optional<dynamics::Matrix6> matrix6(const spec::Reader& r, const YAML::Node& n, const std::string& key) {
  const std::string expected = "expected 6 rows of 6 numbers (surge, sway, heave, roll, pitch, yaw; kg, kg m, kg m^2)";
  if (!n.IsSequence() || n.size() != 6) {
    r.fail(n, key, expected);
    return std::nullopt;
  }
  dynamics::Matrix6 A;
  for (std::size_t i = 0; i < 6; ++i) {
    const YAML::Node row = n[i];
    const std::string rowKey = key + "[" + std::to_string(i) + "]";
    if (!row.IsSequence() || row.size() != 6) {
      r.fail(row, rowKey, expected);
      return std::nullopt;
    }
    for (std::size_t j = 0; j < 6; ++j) {
      double v = 0.0;
      if (!row[j].IsScalar() || !YAML::convert<double>::decode(row[j], v) || !std::isfinite(v)) {
        r.fail(row[j], rowKey + "[" + std::to_string(j) + "]", "expected a number");
        return std::nullopt;
      }
      A(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = v;
    }
  }
  // (A) => refused when A_ij and A_ji differ by more than 1e-6 of the largest entry
  const double scale = A.cwiseAbs().maxCoeff();
  for (Eigen::Index i = 0; i < 6; ++i) {
    for (Eigen::Index j = i + 1; j < 6; ++j) {
      if (std::abs(A(i, j) - A(j, i)) > 1e-6 * scale) {
        r.fail(n, key, "not symmetric: row " + std::to_string(i + 1) + " column " + std::to_string(j + 1) + " is " +
                           std::to_string(A(i, j)) + " but row " + std::to_string(j + 1) + " column " +
                           std::to_string(i + 1) + " is " + std::to_string(A(j, i)));
        return std::nullopt;
      }
    }
  }
  return A;
}

// (follow_draft node) => the drafts, m, finite, > 0 and increasing, or nothing after a report
std::vector<double> drafts(const spec::Reader& r, const YAML::Node& n, const std::string& key) {
  const std::string expected =
      "expected a list of drafts in m, > 0 and increasing (the keel's depth below the still water "
      "at which the "
      "added mass is computed), e.g. [0.25, 0.5, 1, 2]";
  if (!n.IsSequence() || n.size() == 0) {
    r.fail(n, key, expected);
    return {};
  }
  std::vector<double> out;
  for (std::size_t k = 0; k < n.size(); ++k) {
    double v = 0.0;
    const std::string at = key + "[" + std::to_string(k) + "]";
    if (!n[k].IsScalar() || !YAML::convert<double>::decode(n[k], v) || !std::isfinite(v)) {
      r.fail(n[k], at, "expected a number (a draft in m)");
      return {};
    }
    if (!(v > (out.empty() ? 0.0 : out.back()))) {
      r.fail(n[k], at,
             out.empty()
                 ? "expected a draft > 0 m (a dry hull has no added mass: draft 0 is implied)"
                 : "expected a draft greater than the one before (" + std::to_string(out.back()) +
                       " m): the drafts increase");
      return {};
    }
    out.push_back(v);
  }
  return out;
}

}  // namespace

void parseAddedMass(const spec::Reader& r, const YAML::Node& n, const std::string& key, const std::string& yamlFile,
                    MechanicsSpec::Body& b) {
  if (!r.keys(n, {"matrix", "about", "hull", "rho", "follow_draft"}, key)) return;
  if (n["matrix"].IsDefined() == n["hull"].IsDefined()) {
    r.fail(n, key, "give exactly one of 'matrix' (a 6x6 in the naval order) and 'hull' (a mesh to compute it from)");
    return;
  }
  // (matrix, about) => the given added mass
  if (const YAML::Node m = n["matrix"]) {
    if (n["rho"]) r.fail(n["rho"], key + ".rho", "'rho' goes with 'hull' (the computed added mass), not with 'matrix'");
    if (n["follow_draft"])
      r.fail(n["follow_draft"], key + ".follow_draft",
             "'follow_draft' goes with 'hull' (the added mass computed at those drafts), not with "
             "'matrix'");
    b.addedMassAbout = r.length3(n["about"], key + ".about", dynamics::Vector3::Zero());
    b.addedMass = matrix6(r, m, key + ".matrix");
    return;
  }
  // (hull, rho) => the mesh, checked as a closed surface and as panels
  if (n["about"]) r.fail(n["about"], key + ".about", "'about' goes with 'matrix'; a computed added mass is about the body origin");
  if (n["rho"]) {
    b.addedMassRho = r.number(n["rho"], key + ".rho", 0.0);
    if (!(b.addedMassRho > 0.0)) r.fail(n["rho"], key + ".rho", "expected a water density > 0, kg/m^3");
  }
  if (const YAML::Node f = n["follow_draft"])
    b.addedMassDrafts = drafts(r, f, key + ".follow_draft");
  const YAML::Node h = n["hull"];
  if (!h || !h.IsScalar()) {
    r.fail(h ? h : n, key + ".hull",
           "expected the path of a closed hull mesh (.obj or .stl) in the body frame");
    return;
  }
  std::filesystem::path path(h.Scalar());
  if (path.is_relative() && !yamlFile.empty()) path = std::filesystem::path(yamlFile).parent_path() / path;
  try {
    auto mesh = std::make_shared<forces::TriangleMesh>(forces::readClosedMesh(path.lexically_normal().string()));
    forces::hydro::buildPanels(forces::hydro::panelMesh(*mesh));
    b.addedMassHull = std::move(mesh);
  } catch (const std::exception& e) {
    r.fail(h, key + ".hull", e.what());
  }
}

}  // namespace yardsim::scene
