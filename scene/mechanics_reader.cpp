#include "scene/mechanics_reader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <set>

#include "dynamics/model_builder.hpp"
#include "dynamics/rotation.hpp"
#include "forces/geometry/mesh_io.hpp"
#include "models/diagnostics.hpp"
#include "scene/added_mass_reader.hpp"
#include "scene/floating_reader.hpp"
#include "scene/provider_readers.hpp"
#include "scene/providers/lumped_rope_reader.hpp"
#include "scene/spec_reader.hpp"
#include "scene/yard_reader.hpp"

namespace yardsim::scene {

using mechanics::MechanicsSpec;
using models::Params;
using models::didYouMean;
namespace {

using dynamics::Vector3;
using spec::kDeg;
using spec::Reader;

// (joint mapping) => joint type, axes, initial state
void joint(const Reader& r, const YAML::Node& n, const std::string& key, MechanicsSpec::Body& b) {
  b.jointName = b.name + "_joint";
  if (!r.keys(n, {"name", "type", "axis", "axis2", "q0", "q0_deg", "v0", "v0_deg", "hold"}, key))
    return;
  b.jointName = r.text(n["name"], key + ".name", b.jointName);
  if (!r.required(n, "type", key,
                  "fixed, revolute, prismatic, cylindrical, universal, spherical, planar or free"))
    return;
  const std::string type = r.text(n["type"], key + ".type", "");
  const Vector3 axis = r.vec3(n["axis"], key + ".axis", Vector3::UnitZ());
  const Vector3 axis2 = r.vec3(n["axis2"], key + ".axis2", Vector3::UnitY());
  using dynamics::Joint;
  static const std::vector<std::string> types{"fixed",     "revolute",  "prismatic", "cylindrical",
                                              "universal", "spherical", "planar",    "free"};
  if (type == "fixed") b.joint = Joint::fixed();
  else if (type == "revolute") b.joint = Joint::revolute(axis.normalized());
  else if (type == "prismatic") b.joint = Joint::prismatic(axis.normalized());
  else if (type == "cylindrical") b.joint = Joint::cylindrical(axis.normalized());
  else if (type == "universal") b.joint = Joint::universal(axis.normalized(), axis2.normalized());
  else if (type == "spherical") b.joint = Joint::spherical();
  else if (type == "planar") b.joint = Joint::planar();
  else if (type == "free") b.joint = Joint::free();
  else {
    const std::string hint = didYouMean(type, types);
    r.fail(n["type"], key + ".type",
           "unknown joint type '" + type + "'; expected one of fixed, revolute, prismatic, "
           "cylindrical, universal, spherical, planar, free" + (hint.empty() ? "" : " (" + hint + ")"));
    return;
  }
  if (const YAML::Node h = n["hold"]) {
    if (!h.IsScalar() || !YAML::convert<bool>::decode(h, b.hold))
      r.fail(h, key + ".hold", "expected true or false, got '" + (h.IsScalar() ? h.Scalar() : "a collection") + "'");
    else if (b.hold && b.joint.nv() != 1)
      r.fail(h, key + ".hold", "only a 1-dof joint (revolute, prismatic) can be held");
  }
  if ((n["axis"] && axis.norm() < 1e-12) || (n["axis2"] && axis2.norm() < 1e-12))
    r.fail(n["axis"], key + ".axis", "a joint axis must not be zero");
  // (q0 / q0_deg, v0 / v0_deg) => initial state in joint units; free joints take {xyz, rpy_deg}
  const int nq = b.joint.nq(), nv = b.joint.nv();
  auto values = [&](const char* rad, const char* deg, int size) -> std::vector<double> {
    const YAML::Node nr = n[rad], nd = n[deg];
    if (!nr && !nd) return {};
    const double scale = nd ? kDeg : 1.0;
    const YAML::Node v = nd ? nd : nr;
    const std::string k = key + "." + (nd ? deg : rad);
    std::vector<double> out = v.IsSequence() ? r.numbers(v, k, static_cast<std::size_t>(size))
                                             : std::vector<double>{r.number(v, k, 0.0)};
    if (static_cast<int>(out.size()) != size) r.fail(v, k, "expected " + std::to_string(size) + " values");
    for (double& x : out) x *= scale;
    return out;
  };
  if (b.joint.type == dynamics::JointType::Free || b.joint.type == dynamics::JointType::Spherical) {
    if (const YAML::Node q = n["q0"]) {
      const auto X = r.pose(q, key + ".q0");
      b.q0.assign(static_cast<std::size_t>(nq), 0.0);
      double quat[4];
      dynamics::matrixToQuaternion(X.R, quat);
      int off = 0;
      if (b.joint.type == dynamics::JointType::Free) {
        for (int i = 0; i < 3; ++i) b.q0[static_cast<std::size_t>(i)] = X.p[i];
        off = 3;
      }
      for (int i = 0; i < 4; ++i) b.q0[static_cast<std::size_t>(off + i)] = quat[i];
    }
    b.v0 = values("v0", "v0_deg", nv);
  } else {
    b.q0 = values("q0", "q0_deg", nq);
    b.v0 = values("v0", "v0_deg", nv);
  }
}

// ({box | cylinder | sphere | mesh, pose}) => what the replay draws for the body
MechanicsSpec::Visual visual(const Reader& r, const YAML::Node& n, const std::string& key,
                             const std::filesystem::path& dir) {
  using Shape = MechanicsSpec::Visual::Shape;
  MechanicsSpec::Visual v;
  const char* expected = "expected one of {box: [lx, ly, lz]}, {cylinder: {radius, length}}, "
                         "{sphere: radius}, {mesh: file}, with an optional pose: {xyz, rpy_deg}";
  if (!n.IsMap()) {
    r.fail(n, key, expected);
    return v;
  }
  if (!r.keys(n, {"box", "cylinder", "sphere", "mesh", "pose"}, key)) return v;
  const int shapes = (n["box"] ? 1 : 0) + (n["cylinder"] ? 1 : 0) + (n["sphere"] ? 1 : 0) + (n["mesh"] ? 1 : 0);
  if (shapes != 1) {
    r.fail(n, key, std::string(shapes ? "more than one shape; " : "no shape; ") + expected);
    return v;
  }
  auto positive = [&](const YAML::Node& at, const std::string& k, double x) {
    if (!(x > 0)) r.fail(at, k, "must be > 0 m");
  };
  if (const YAML::Node b = n["box"]) {
    v.shape = Shape::Box;
    v.size = r.length3(b, key + ".box", Vector3::Zero());
    if (b.IsSequence() && b.size() == 3 && !(v.size.minCoeff() > 0)) positive(b, key + ".box", 0.0);
  } else if (YAML::Node c = n["cylinder"]) {  // not const: a missing key must stay a valid node
    v.shape = Shape::Cylinder;
    if (r.keys(c, {"radius", "length"}, key + ".cylinder")) {
      v.size[0] = r.number(c["radius"], key + ".cylinder.radius", 0.0, true);
      v.size[1] = r.number(c["length"], key + ".cylinder.length", 0.0, true);
      if (c["radius"]) positive(c["radius"], key + ".cylinder.radius", v.size[0]);
      if (c["length"]) positive(c["length"], key + ".cylinder.length", v.size[1]);
    }
  } else if (const YAML::Node s = n["sphere"]) {
    v.shape = Shape::Sphere;
    v.size[0] = r.number(s, key + ".sphere", 0.0);
    positive(s, key + ".sphere", v.size[0]);
  } else {
    v.shape = Shape::Mesh;
    const YAML::Node m = n["mesh"];
    v.file = m.IsScalar() ? m.Scalar() : "";
    try {
      if (m.IsMap() && m["database"] && m["block"]) {  // a block's mesh from the yard database
        v.file = m["block"].Scalar();
        v.mesh = databaseBlockMesh(m["database"].Scalar(), v.file);
      } else if (v.file.empty())
        throw forces::MeshError("expected a file name (OBJ or STL, relative to this YAML file)");
      else
        v.mesh = std::make_shared<const forces::TriangleMesh>(
            forces::readMesh((dir / v.file).lexically_normal().string()));
    } catch (const forces::MeshError& e) {
      r.fail(m, key + ".mesh", e.what());
    }
  }
  if (n["pose"]) {
    v.posed = true;
    v.X_BG = r.pose(n["pose"], key + ".pose");
  }
  return v;
}

}  // namespace

MechanicsSpec parseMechanics(const Params& p, const MechanicsReport& report) {
  MechanicsSpec spec;
  const Reader top{report, "gravity"};
  spec.gravity = top.vec3(p.node("gravity"), "", spec.gravity);
  // (optional system-wide settings) => spec.settings
  auto setting = [&](const char* key, double& value, bool positive) {
    if (!p.has(key)) return;
    const Reader sr{report, key};
    value = sr.number(p.node(key), "", value);
    if (positive ? !(value > 0) : value < 0)
      sr.fail(p.node(key), "", positive ? "must be > 0" : "must be >= 0");
  };
  setting("drive_bandwidth", spec.settings.driveBandwidth, false);
  setting("drive_max_effort", spec.settings.driveMaxEffort, false);
  setting("drive_tolerance", spec.settings.driveTolerance, true);
  if (p.has("equilibrium")) {
    const YAML::Node e = p.node("equilibrium");
    if (!e.IsScalar() || !YAML::convert<bool>::decode(e, spec.settings.equilibrium))
      Reader{report, "equilibrium"}.fail(e, "", "expected true or false");
  }

  const Reader r{report, "bodies"};
  const YAML::Node bodies = p.node("bodies");
  if (!bodies.IsMap() || bodies.size() == 0) {
    r.fail(bodies, "", "expected a mapping of at least one body: {name: {parent, joint, mass, ...}}");
    return spec;
  }
  std::set<std::string> names{"world"};
  for (auto it = bodies.begin(); it != bodies.end(); ++it) {
    MechanicsSpec::Body b;
    b.name = it->first.as<std::string>();
    const YAML::Node n = it->second;
    if (!names.insert(b.name).second) {
      r.fail(it->first, b.name, "duplicate body name '" + b.name + "'");
      continue;
    }
    if (!r.keys(n, {"parent", "joint", "placement", "mass", "com", "inertia", "geometry", "added_mass"}, b.name))
      continue;
    if (r.required(n, "parent", b.name, "a body name or world"))
      b.parent = r.text(n["parent"], b.name + ".parent", "");
    if (r.required(
            n, "joint", b.name,
            "{type: revolute|prismatic|cylindrical|universal|spherical|planar|fixed|free, ...}"))
      joint(r, n["joint"], b.name + ".joint", b);
    else
      b.jointName = b.name + "_joint";
    b.X_PJ = r.pose(n["placement"], b.name + ".placement");
    if (r.required(n, "mass", b.name, "kg")) b.mass = r.number(n["mass"], b.name + ".mass", 0.0);
    if (n["mass"] && !(b.mass > 0)) r.fail(n["mass"], b.name + ".mass", "mass must be > 0 kg");
    b.com = r.length3(n["com"], b.name + ".com", Vector3::Zero());
    if (const YAML::Node in = n["inertia"]) {
      const auto v = in.IsSequence() && in.size() == 6 ? r.numbers(in, b.name + ".inertia", 6)
                                                        : r.numbers(in, b.name + ".inertia", 3);
      b.inertia.diagonal() << v[0], v[1], v[2];
      if (v.size() == 6) {
        b.inertia(0, 1) = b.inertia(1, 0) = v[3];
        b.inertia(0, 2) = b.inertia(2, 0) = v[4];
        b.inertia(1, 2) = b.inertia(2, 1) = v[5];
      }
    } else {
      r.fail(n, b.name, "missing required key 'inertia' ([Ixx, Iyy, Izz] or [Ixx, Iyy, Izz, Ixy, "
                        "Ixz, Iyz] about the centre of mass, kg m^2)");
    }
    if (const YAML::Node g = n["geometry"]) {
      b.visual = visual(r, g, b.name + ".geometry", std::filesystem::path(p.mark("bodies").file).parent_path());
      YAML::Emitter e;
      e.SetMapFormat(YAML::Flow);
      e.SetSeqFormat(YAML::Flow);
      e << g;
      b.geometry = e.c_str();
    }
    if (const YAML::Node am = n["added_mass"]) {
      parseAddedMass(r, am, b.name + ".added_mass", p.mark("bodies").file, b);
    }
    spec.bodies.push_back(std::move(b));
  }
  for (const auto& b : spec.bodies)
    if (!b.parent.empty() && !names.count(b.parent)) {
      std::vector<std::string> known(names.begin(), names.end());
      const std::string hint = didYouMean(b.parent, known);
      r.fail(bodies[b.name]["parent"], b.name + ".parent",
             "unknown parent body '" + b.parent + "'" + (hint.empty() ? "" : " (" + hint + ")"));
    }

  const YAML::Node loops = p.node("loops");
  const Reader lr{report, "loops"};
  if (loops.IsMap()) {
    for (auto it = loops.begin(); it != loops.end(); ++it) {
      MechanicsSpec::Loop l;
      l.name = it->first.as<std::string>();
      const YAML::Node n = it->second;
      if (!lr.keys(n, {"body_a", "frame_a", "body_b", "frame_b", "constrain"}, l.name)) continue;
      l.bodyA = lr.text(n["body_a"], l.name + ".body_a", "");
      l.bodyB = lr.text(n["body_b"], l.name + ".body_b", "");
      for (const char* end : {"body_a", "body_b"}) {
        const std::string& bn = end[5] == 'a' ? l.bodyA : l.bodyB;
        if (!names.count(bn))
          lr.fail(n[end] ? n[end] : n, l.name + "." + end,
                  "unknown body '" + bn + "' in loop '" + l.name + "'");
      }
      l.X_AF = lr.pose(n["frame_a"], l.name + ".frame_a");
      l.X_BG = lr.pose(n["frame_b"], l.name + ".frame_b");
      const std::string c = lr.text(n["constrain"], l.name + ".constrain", "point");
      if (c == "point")
        l.mask = dynamics::kPointConstraint;
      else if (c == "axis")
        l.mask = dynamics::kAxisConstraint;
      else if (c == "cylinder")
        l.mask = dynamics::kCylinderConstraint;
      else if (c == "weld")
        l.mask = dynamics::kAxisConstraint | dynamics::kRotZ;
      else if (c == "planar_point")
        l.mask = dynamics::kPlanarPointConstraint;  // x, y of frame_a
      else
        lr.fail(n["constrain"], l.name + ".constrain",
                "expected point, axis, cylinder, weld or planar_point, got '" + c + "'");
      spec.loops.push_back(std::move(l));
    }
  } else if (loops.IsDefined() && !loops.IsNull()) {
    lr.fail(loops, "", "expected a mapping of loop closures");
  }
  // ({body, point}) => a point on a body, checked
  auto point = [&](const Reader& rd, const YAML::Node& n, const std::string& k) {
    MechanicsSpec::Point out{"world", Vector3::Zero()};
    if (!rd.keys(n, {"body", "point"}, k)) return out;
    out.first = rd.text(n["body"], k + ".body", "world");
    if (!names.count(out.first)) {
      std::vector<std::string> known(names.begin(), names.end());
      const std::string hint = didYouMean(out.first, known);
      rd.fail(n["body"], k + ".body", "unknown body '" + out.first + "'" + (hint.empty() ? "" : " (" + hint + ")"));
    }
    out.second = rd.length3(n["point"], k + ".point", Vector3::Zero());
    return out;
  };
  // (a list of points) => the points, at least `least` of them
  auto points = [&](const Reader& rd, const YAML::Node& n, const std::string& k, std::size_t least) {
    std::vector<MechanicsSpec::Point> out;
    if (!n.IsSequence() || n.size() < least) {
      rd.fail(n, k, "expected a list of at least " + std::to_string(least) + " points {body, point: [x, y, z]}");
      return out;
    }
    for (std::size_t i = 0; i < n.size(); ++i) out.push_back(point(rd, n[i], k + "[" + std::to_string(i) + "]"));
    return out;
  };
  // (EA, L0, damping, min_length, mbl, diameter) => the rope material, checked
  auto material = [](const Reader& rd, const YAML::Node& n, const std::string& k) {
    MechanicsSpec::Material m;
    if (rd.required(n, "EA", k, "N, the axial stiffness of one part"))
      m.ea = rd.number(n["EA"], k + ".EA", 0.0);
    if (rd.required(n, "L0", k, "m, the unstretched length"))
      m.l0 = rd.number(n["L0"], k + ".L0", 0.0);
    m.damping = rd.number(n["damping"], k + ".damping", 0.0);
    m.minLength = rd.number(n["min_length"], k + ".min_length", 0.01);
    m.mbl = rd.number(n["mbl"], k + ".mbl", 0.0);
    m.diameter = rd.number(n["diameter"], k + ".diameter", 0.0);
    if (n["diameter"] && !(m.diameter > 0))
      rd.fail(n["diameter"], k + ".diameter", "diameter must be > 0 m");
    if (n["EA"] && !(m.ea > 0)) rd.fail(n["EA"], k + ".EA", "EA must be > 0 N");
    if (n["L0"] && !(m.l0 > 0)) rd.fail(n["L0"], k + ".L0", "L0 must be > 0 m");
    if (m.damping < 0) rd.fail(n["damping"], k + ".damping", "damping must be >= 0 N s/m");
    if (n["mbl"] && !(m.mbl > 0)) rd.fail(n["mbl"], k + ".mbl", "mbl must be > 0 N (leave it out for a rope without one)");
    return m;
  };
  const std::vector<std::string> materialKeys{"EA",         "L0",  "damping",
                                              "min_length", "mbl", "diameter"};

  const YAML::Node ropes = p.node("ropes");
  const Reader rr{report, "ropes"};
  if (ropes.IsMap()) {
    for (auto it = ropes.begin(); it != ropes.end(); ++it) {
      MechanicsSpec::Rope rope;
      rope.name = it->first.as<std::string>();
      const YAML::Node n = it->second;
      const std::string k = rope.name;
      if (providers::readLumpedRope(rr, n, k, spec)) continue;  // model: lumped, else massless
      auto keys = materialKeys;
      keys.insert(keys.end(), {"path", "parts", "model"});
      if (!rr.keys(n, keys, k)) continue;
      if (rr.required(n, "path", k, "a list of at least 2 points {body, point: [x, y, z]}"))
        rope.path = points(rr, n["path"], k + ".path", 2);
      rope.material = material(rr, n, k);
      const double parts = rr.number(n["parts"], k + ".parts", 1.0);
      // (parts) => the count, cast only once it is known to be a whole number in range
      if (parts < 1 || parts > 1000 || parts != std::floor(parts))
        rr.fail(n["parts"], k + ".parts", "parts must be a whole number from 1 to 1000, got " + std::to_string(parts));
      else
        rope.parts = static_cast<int>(parts);
      spec.ropes.push_back(std::move(rope));
    }
  } else if (ropes.IsDefined() && !ropes.IsNull()) {
    rr.fail(ropes, "", "expected a mapping of wire ropes");
  }

  const YAML::Node eqs = p.node("equalizers");
  const Reader er{report, "equalizers"};
  if (eqs.IsMap()) {
    for (auto it = eqs.begin(); it != eqs.end(); ++it) {
      MechanicsSpec::Equalizer eq;
      eq.name = it->first.as<std::string>();
      const YAML::Node n = it->second;
      const std::string k = eq.name;
      auto keys = materialKeys;
      keys.insert(keys.end(), {"sheave", "branches"});
      if (!er.keys(n, keys, k)) continue;
      if (er.required(n, "sheave", k, "{body, point: [x, y, z]}"))
        eq.sheave = point(er, n["sheave"], k + ".sheave");
      const YAML::Node br = n["branches"];
      if (!br || !br.IsSequence() || br.size() < 2) {
        er.fail(br ? br : n, k + ".branches",
                "expected a list of at least 2 branches, each a list of points");
      } else {
        for (std::size_t j = 0; j < br.size(); ++j)
          eq.branches.push_back(points(er, br[j], k + ".branches[" + std::to_string(j) + "]", 1));
      }
      eq.material = material(er, n, k);
      spec.equalizers.push_back(std::move(eq));
    }
  } else if (eqs.IsDefined() && !eqs.IsNull()) {
    er.fail(eqs, "", "expected a mapping of equalizers");
  }

  // (loads: name: {body, point, frame, series}) => body loads
  const YAML::Node loads = p.has("loads") ? p.node("loads") : YAML::Node();
  const Reader ldr{report, "loads"};
  if (loads.IsMap()) {
    for (auto it = loads.begin(); it != loads.end(); ++it) {
      MechanicsSpec::Load l;
      l.name = it->first.as<std::string>();
      const YAML::Node n = it->second;
      if (!ldr.keys(n, {"body", "point", "frame", "series"}, l.name)) continue;
      if (ldr.required(n, "body", l.name, "the body it acts on"))
        l.body = ldr.text(n["body"], l.name + ".body", "");
      if (!l.body.empty() && (!names.count(l.body) || l.body == "world"))
        ldr.fail(n["body"], l.name + ".body", "unknown body '" + l.body + "'");
      l.point = ldr.length3(n["point"], l.name + ".point", Vector3::Zero());
      const std::string frame = n["frame"] && n["frame"].IsScalar() ? n["frame"].Scalar() : "world";
      if (frame != "world" && frame != "body")
        ldr.fail(n["frame"], l.name + ".frame", "expected world or body, got '" + frame + "'");
      l.bodyFrame = frame == "body";
      const YAML::Node series = n["series"];
      if (!series || !series.IsSequence() || series.size() == 0) {
        ldr.fail(series ? series : n, l.name + ".series",
                 "expected a list of rows [t, fx, fy, fz, mx, my, mz] (s, N, N m)");
        continue;
      }
      double last = -std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < series.size(); ++i) {
        const std::string k = l.name + ".series[" + std::to_string(i) + "]";
        const auto row = ldr.numbers(series[i], k, 7);
        std::array<double, 7> sample{};
        std::copy(row.begin(), row.end(), sample.begin());
        if (sample[0] < last) ldr.fail(series[i], k, "times must not decrease");
        last = sample[0];
        l.series.push_back(sample);
      }
      spec.loads.push_back(std::move(l));
    }
  } else if (loads.IsDefined() && !loads.IsNull()) {
    ldr.fail(loads, "", "expected a mapping of body loads");
  }

  // (watch: name: {channel, above | below}) => watched quantities
  const YAML::Node watch = p.has("watch") ? p.node("watch") : YAML::Node();
  const Reader wr{report, "watch"};
  if (watch.IsMap()) {
    const std::vector<std::string> quantities{"q", "v", "x", "y", "z", "roll", "pitch", "yaw", "tension", "length"};
    for (auto it = watch.begin(); it != watch.end(); ++it) {
      MechanicsSpec::Watch w;
      w.name = it->first.as<std::string>();
      const YAML::Node n = it->second;
      if (!wr.keys(n, {"channel", "above", "below"}, w.name)) continue;
      const std::string channel = n["channel"] && n["channel"].IsScalar() ? n["channel"].Scalar() : "";
      const auto dot = channel.rfind('.');
      if (dot == std::string::npos || dot == 0) {
        wr.fail(n["channel"], w.name + ".channel",
                "expected <element>.<quantity>, e.g. block.roll or hoist.tension, got '" + channel + "'");
        continue;
      }
      w.element = channel.substr(0, dot);
      w.quantity = channel.substr(dot + 1);
      if (std::find(quantities.begin(), quantities.end(), w.quantity) == quantities.end()) {
        const std::string hint = didYouMean(w.quantity, quantities);
        wr.fail(n["channel"], w.name + ".channel",
                "cannot watch '" + w.quantity + "'; expected q, v (joints), x, y, z, roll, pitch, yaw "
                "(bodies), tension, length (ropes)" + (hint.empty() ? "" : " (" + hint + ")"));
      }
      if (bool(n["above"]) == bool(n["below"])) {
        wr.fail(n, w.name, "give exactly one of above and below (the threshold, in the quantity's SI unit)");
        continue;
      }
      w.above = bool(n["above"]);
      w.threshold = wr.number(w.above ? n["above"] : n["below"], w.name + (w.above ? ".above" : ".below"), 0.0);
      // (element) => one of this spec's joints, bodies or ropes (a fragment resolves it later)
      std::vector<std::string> elements;
      for (const auto& b : spec.bodies) elements.insert(elements.end(), {b.name, b.jointName});
      for (const auto& rope : spec.ropes) elements.push_back(rope.name);
      if (std::find(elements.begin(), elements.end(), w.element) == elements.end()) {
        const std::string hint = didYouMean(w.element, elements);
        wr.fail(n["channel"], w.name + ".channel",
                "unknown element '" + w.element + "'" + (hint.empty() ? "" : " (" + hint + ")"));
      }
      spec.watches.push_back(std::move(w));
    }
  } else if (watch.IsDefined() && !watch.IsNull()) {
    wr.fail(watch, "", "expected a mapping of watched quantities");
  }
  parseFloating(p, report, names, spec);
  // (registered readers' keys) => their providers, attachments checked like a rope's
  for (const ProviderReader& reader : providerReaders()) {
    if (!p.has(reader.key)) continue;
    const YAML::Node block = p.node(reader.key);
    const Reader br{report, reader.key};
    if (block.IsNull() || (block.IsMap() && block.size() == 0)) continue;
    if (!block.IsMap()) {
      br.fail(block, "", "expected a mapping of named entries (" + reader.summary + ")");
      continue;
    }
    for (auto it = block.begin(); it != block.end(); ++it) {
      const std::string name = it->first.as<std::string>();
      MechanicsSpec::ProviderSpec ps = reader.read(name, it->second, br, name);
      ps.kind = reader.key;
      ps.name = name;
      for (std::size_t i = 0; i < ps.attachments.size(); ++i) {
        const std::string& body = ps.attachments[i].first;
        if (body == "world" || names.count(body)) continue;
        std::vector<std::string> known(names.begin(), names.end());
        const std::string hint = didYouMean(body, known);
        br.fail(it->second, name, "unknown body '" + body + "'" + (hint.empty() ? "" : " (" + hint + ")"));
      }
      if (!ps.build && !ps.buildFromSystem) br.fail(it->second, name, "the reader of '" + reader.key + "' built nothing");
      else spec.providers.push_back(std::move(ps));
    }
  }
  return spec;
}

}  // namespace yardsim::scene
