#include "models/multibody/added_mass_spec.hpp"

#include <cmath>
#include <filesystem>

#include "dynamics/added_mass.hpp"
#include "dynamics/data.hpp"
#include "dynamics/kinematics.hpp"
#include "forces/geometry/mesh_io.hpp"
#include "forces/hydro/added_mass.hpp"
#include "models/diagnostics.hpp"

namespace yardsim::models {

namespace {

// (node) => the node itself when it has a position, else its first descendant that has one:
// '$name' resolution rebuilds mappings and lists without positions (models/yaml_source.cpp), only
// their scalars keep theirs
YAML::Node located(const YAML::Node& n) {
  if (!n.IsDefined() || !n.Mark().is_null() || n.IsScalar()) return n;
  for (auto it = n.begin(); it != n.end(); ++it) {
    const YAML::Node child = n.IsMap() ? it->second : *it;
    const YAML::Node at = located(child);
    if (!at.Mark().is_null()) return at;
  }
  return n;
}

// (matrix node) => 6x6, or nothing after a report
std::optional<dynamics::Matrix6> matrix6(const YAML::Node& n, const std::string& key, const AddedMassReport& report) {
  const std::string expected = "expected 6 rows of 6 numbers (surge, sway, heave, roll, pitch, yaw; kg, kg m, kg m^2)";
  if (!n.IsSequence() || n.size() != 6) {
    report(n, key, expected);
    return std::nullopt;
  }
  dynamics::Matrix6 A;
  for (std::size_t i = 0; i < 6; ++i) {
    const YAML::Node row = n[i];
    if (!row.IsSequence() || row.size() != 6) {
      report(row, key + "[" + std::to_string(i) + "]", expected);
      return std::nullopt;
    }
    for (std::size_t j = 0; j < 6; ++j) {
      double v = 0.0;
      if (!row[j].IsScalar() || !YAML::convert<double>::decode(row[j], v) || !std::isfinite(v)) {
        report(row[j], key + "[" + std::to_string(i) + "][" + std::to_string(j) + "]", "expected a number");
        return std::nullopt;
      }
      A(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = v;
    }
  }
  const double scale = A.cwiseAbs().maxCoeff();
  for (Eigen::Index i = 0; i < 6; ++i) {
    for (Eigen::Index j = i + 1; j < 6; ++j) {
      if (std::abs(A(i, j) - A(j, i)) > 1e-6 * scale) {
        report(n, key, "not symmetric: row " + std::to_string(i + 1) + " column " + std::to_string(j + 1) + " is " +
                           std::to_string(A(i, j)) + " but row " + std::to_string(j + 1) + " column " +
                           std::to_string(i + 1) + " is " + std::to_string(A(j, i)));
        return std::nullopt;
      }
    }
  }
  return A;
}

}  // namespace

void parseAddedMass(const YAML::Node& n, const std::string& key, const std::string& yamlFile,
                    const AddedMassReport& reportAt, MechanicsSpec::Body& b) {
  const AddedMassReport report = [&](const YAML::Node& at, const std::string& k, const std::string& msg) {
    reportAt(located(at), k, msg);
  };
  if (!n.IsMap()) {
    report(n, key, "expected a mapping: {matrix: [[...] x 6], about: [x, y, z]} or {hull: file.obj, rho: 1025}");
    return;
  }
  const std::vector<std::string> allowed{"matrix", "about", "hull", "rho"};
  for (auto it = n.begin(); it != n.end(); ++it) {
    const auto k = it->first.as<std::string>();
    if (std::find(allowed.begin(), allowed.end(), k) != allowed.end()) continue;
    const std::string hint = didYouMean(k, allowed);
    report(it->first.Mark().is_null() ? it->second : it->first, key + "." + k,
           "unknown key '" + k + "'" + (hint.empty() ? "" : " (" + hint + ")"));
  }
  if (n["matrix"].IsDefined() == n["hull"].IsDefined()) {
    report(n, key, "give exactly one of 'matrix' (a 6x6 in the naval order) and 'hull' (a mesh to compute it from)");
    return;
  }
  // (matrix, about) => the given added mass
  if (const YAML::Node m = n["matrix"]) {
    if (n["rho"]) report(n["rho"], key + ".rho", "'rho' goes with 'hull' (the computed added mass), not with 'matrix'");
    if (const YAML::Node about = n["about"]) {
      double p[3] = {0, 0, 0};
      const bool ok = about.IsSequence() && about.size() == 3 && YAML::convert<double>::decode(about[0], p[0]) &&
                      YAML::convert<double>::decode(about[1], p[1]) && YAML::convert<double>::decode(about[2], p[2]);
      if (!ok) report(about, key + ".about", "expected [x, y, z], m (the reference point in the body frame)");
      b.addedMassAbout = dynamics::Vector3(p[0], p[1], p[2]);
    }
    b.addedMass = matrix6(m, key + ".matrix", report);
    return;
  }
  // (hull, rho) => the mesh, checked as a closed surface and as panels
  if (n["about"]) report(n["about"], key + ".about", "'about' goes with 'matrix'; a computed added mass is about the body origin");
  const YAML::Node h = n["hull"];
  if (const YAML::Node rho = n["rho"]) {
    if (!rho.IsScalar() || !YAML::convert<double>::decode(rho, b.addedMassRho) || !(b.addedMassRho > 0.0) ||
        !std::isfinite(b.addedMassRho))
      report(rho, key + ".rho", "expected a water density > 0, kg/m^3");
  }
  if (!h.IsScalar()) {
    report(h, key + ".hull", "expected the path of a closed hull mesh (.obj or .stl) in the body frame");
    return;
  }
  std::filesystem::path path(h.Scalar());
  if (path.is_relative() && !yamlFile.empty()) path = std::filesystem::path(yamlFile).parent_path() / path;
  try {
    auto mesh = std::make_shared<forces::TriangleMesh>(forces::readClosedMesh(path.string()));
    forces::hydro::buildPanels(forces::hydro::panelMesh(*mesh));
    b.addedMassHull = std::move(mesh);
  } catch (const std::exception& e) {
    report(h, key + ".hull", e.what());
  }
}

void setGivenAddedMass(const std::vector<MechanicsSpec::Body>& bodies, dynamics::ModelBuilder& builder) {
  for (const auto& b : bodies) {
    if (b.addedMass) builder.setAddedMass(b.name, dynamics::addedMassAboutOrigin(*b.addedMass, b.addedMassAbout));
  }
}

bool needsHullAddedMass(const std::vector<MechanicsSpec::Body>& bodies) {
  return std::any_of(bodies.begin(), bodies.end(), [](const auto& b) { return b.addedMassHull != nullptr; });
}

void setHullAddedMass(const dynamics::Model& model, const Eigen::VectorXd& q0,
                      const std::vector<MechanicsSpec::Body>& bodies, dynamics::ModelBuilder& builder) {
  // (q0) => X_WB of each body at its mean position
  dynamics::Data d(model);
  dynamics::forwardKinematics(model, d, q0);
  for (const auto& b : bodies) {
    if (!b.addedMassHull) continue;
    const int i = model.bodyIndex(b.name);
    try {
      // (hull, X_WB) => body-axes added mass about the origin, symmetrised (the discrete one is
      // symmetric to discretisation accuracy only)
      const dynamics::Matrix6 A = forces::hydro::floatingAddedMass(forces::hydro::panelMesh(*b.addedMassHull),
                                                                   d.X_WB[static_cast<std::size_t>(i)], b.addedMassRho);
      builder.setAddedMass(b.name, dynamics::addedMassAboutOrigin(0.5 * (A + A.transpose()), dynamics::Vector3::Zero()));
    } catch (const std::exception& e) {
      throw dynamics::ModelError("body '" + b.name + "': added mass from hull '" + b.addedMassHull->source + "': " + e.what());
    }
  }
}

}  // namespace yardsim::models
