#pragma once
// The mechanics a `multibody` component declares in YAML — bodies (mass, centre of mass,
// inertia about the centre of mass), the joint attaching each to its parent and where, loop
// closures, initial state, gravity, step — parsed and checked with positions, then built into
// an immutable dynamics::Model with its initial q and v.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <yaml-cpp/yaml.h>

#include "dynamics/model.hpp"
#include "forces/airy_waves.hpp"
#include "forces/current_profile.hpp"
#include "forces/flow_load.hpp"
#include "forces/geometry/triangle_mesh.hpp"
#include "forces/linear_quadratic_damping.hpp"
#include "forces/wind_profile.hpp"
#include "models/params.hpp"

namespace yardsim::models {

struct MechanicsSpec {
  struct Body {
    std::string name, parent, jointName, geometry;
    dynamics::Joint joint;
    dynamics::Transform X_PJ;  // joint frame in the parent's frame
    double mass = 0.0;
    dynamics::Vector3 com = dynamics::Vector3::Zero();
    dynamics::Matrix3 inertia = dynamics::Matrix3::Zero();  // about the centre of mass
    std::vector<double> q0, v0;  // empty: neutral / at rest
    // added mass (models/multibody/added_mass_spec.hpp): given in the naval order about
    // addedMassAbout (body frame), or computed from addedMassHull at the initial position
    std::optional<dynamics::Matrix6> addedMass;
    dynamics::Vector3 addedMassAbout = dynamics::Vector3::Zero();
    std::shared_ptr<const forces::TriangleMesh> addedMassHull;
    double addedMassRho = 0.0;  // kg/m^3; 0: the scene's water density
  };
  struct Loop {
    std::string name, bodyA, bodyB;
    dynamics::Transform X_AF, X_BG;
    std::uint8_t mask = 0;
  };
  using Point = std::pair<std::string, dynamics::Vector3>;  // (body, p_B)
  struct Material {
    double ea = 0.0, l0 = 0.0, damping = 0.0, minLength = 0.01, mbl = 0.0;  // mbl 0: none
  };
  struct Rope {
    std::string name;
    std::vector<Point> path;  // first end, sheaves, last end
    Material material;
    int parts = 1;
  };
  // k >= 2 branches from one equalizing sheave, one total unstretched length and tension
  struct Equalizer {
    std::string name;
    Point sheave;
    std::vector<std::vector<Point>> branches;  // per branch: sheaves..., end
    Material material;                         // l0: all branches together
  };
  // hydrostatics on a body: its hull mesh, read, checked and placed in the body frame
  struct Hull {
    std::string name, body;
    std::shared_ptr<const forces::TriangleMesh> mesh;
  };
  // a wind or current load on a body (OCIMF style)
  struct Flow {
    std::string name, body;
    dynamics::Vector3 point = dynamics::Vector3::Zero();
    forces::FlowAreas areas;
    forces::FlowCoefficients coefficients;
  };
  struct Damper {
    std::string name, body;
    dynamics::Vector3 point = dynamics::Vector3::Zero();
    forces::DampingCoefficients coefficients;
  };
  dynamics::Vector3 gravity{0.0, 0.0, -9.81};
  std::vector<Body> bodies;
  std::vector<Loop> loops;
  std::vector<Rope> ropes;
  std::vector<Equalizer> equalizers;
  // the environment (scene root only): the sea with its waves and current, the wind
  bool hasWater = false;  // `water:` declared (hydrostatics without it use the defaults)
  forces::WaterProperties water;
  std::vector<forces::WaveComponent> waves;
  std::optional<forces::CurrentProperties> current;
  std::optional<forces::WindProperties> wind;
  std::vector<Hull> hulls;
  std::vector<Flow> windLoads, currentLoads;
  std::vector<Damper> dampers;
};

// Where parsing reports a problem: (node, key path below the parameter, message, hint).
using MechanicsReport =
    std::function<void(const std::string& param, const YAML::Node& at, const std::string& key,
                       const std::string& message)>;

// (params gravity, bodies, loops) => spec; every problem reported with its node
MechanicsSpec parseMechanics(const Params& params, const MechanicsReport& report);

struct BuiltMechanics {
  dynamics::Model model;
  Eigen::VectorXd q0, v0;
  std::vector<std::string> jointNames;  // per body index (0: world, "")
  std::vector<MechanicsSpec::Rope> ropes;
  std::vector<MechanicsSpec::Equalizer> equalizers;
  MechanicsSpec environment;  // water, waves, current, wind, hulls, flow loads, dampers (no bodies)
};

// (spec) => "" or what is missing for its loads: a wind load without `wind:`, a current load
// without `water: {current}`
std::string missingEnvironment(const MechanicsSpec& spec);

// (spec) => model and initial state; throws dynamics::ModelError naming the body
BuiltMechanics buildMechanics(const MechanicsSpec& spec);

}  // namespace yardsim::models
