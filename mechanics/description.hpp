#pragma once
// The description of one mechanical system, as a scene declares it (scene/mechanics_reader.hpp
// reads it from YAML): bodies (mass, centre of mass, inertia about the centre of mass, SI units,
// body frame), the joint attaching each to its parent and where, loop closures, initial state,
// ropes, equalizers, loads, watches and the environment; and the same once built (build.hpp)
// into an immutable dynamics::Model with its initial q and v.
#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dynamics/model.hpp"
#include "forces/airy_waves.hpp"
#include "forces/current_profile.hpp"
#include "forces/flow_load.hpp"
#include "forces/force_provider.hpp"
#include "forces/geometry/triangle_mesh.hpp"
#include "forces/hydro/draft_added_mass.hpp"
#include "forces/hydro/marching_step.hpp"
#include "forces/linear_quadratic_damping.hpp"
#include "forces/rope_path.hpp"
#include "forces/wind_profile.hpp"

namespace yardsim::mechanics {

struct BuiltMechanics;

struct MechanicsSpec {
  // What the report's 3D replay draws for a body; not used by the dynamics. Shape Auto is the
  // uniform box with the body's mass and principal moments of inertia; a mesh (OBJ or STL,
  // relative to the YAML file) is in the body frame unless posed.
  struct Visual {
    enum class Shape { Auto, Box, Cylinder, Sphere, Mesh };
    Shape shape = Shape::Auto;
    dynamics::Vector3 size = dynamics::Vector3::Zero();  // box: lx, ly, lz; cylinder: radius,
                                                         // length (along z); sphere: radius
    std::string file;                                    // mesh: the file as written
    std::shared_ptr<const forces::TriangleMesh> mesh;    // mesh: read at the door, body frame
    bool posed = false;  // false: centred on the centre of mass, along the body axes
    dynamics::Transform X_BG = dynamics::Transform::identity();  // shape frame in the body frame
  };
  struct Body {
    std::string name, parent, jointName, geometry;
    dynamics::Joint joint;
    dynamics::Transform X_PJ;  // joint frame in the parent's frame
    double mass = 0.0;
    dynamics::Vector3 com = dynamics::Vector3::Zero();
    dynamics::Matrix3 inertia = dynamics::Matrix3::Zero();  // about the centre of mass
    std::vector<double> q0, v0;                             // empty: neutral / at rest
    bool hold = false;  // a 1-dof joint's servo holds q0 until an actor drives it (brake)
    Visual visual;
    // added mass (models/multibody/added_mass_spec.hpp): given in the naval order about
    // addedMassAbout (body frame), or computed from addedMassHull at the initial position
    std::optional<dynamics::Matrix6> addedMass;
    dynamics::Vector3 addedMassAbout = dynamics::Vector3::Zero();
    std::shared_ptr<const forces::TriangleMesh> addedMassHull;
    double addedMassRho = 0.0;  // kg/m^3; 0: the scene's water density
    // m, increasing, > 0: addedMassHull's A-infinity is tabulated at these drafts and follows the
    // body's draft (forces/hydro/draft_added_mass.hpp); empty: constant, at the initial position
    std::vector<double> addedMassDrafts;
  };
  struct Loop {
    std::string name, bodyA, bodyB;
    dynamics::Transform X_AF, X_BG;
    std::uint8_t mask = 0;
  };
  using Point = std::pair<std::string, dynamics::Vector3>;  // (body, p_B)
  struct Material {
    double ea = 0.0, l0 = 0.0, damping = 0.0, minLength = 0.01, mbl = 0.0;  // mbl 0: none
    double diameter = 0.0;  // m, the rope's own (collision capsules); 0: not given
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
  // System-wide settings: the `multibody` type's params, or the scene root's `mechanics:`
  struct Settings {
    double driveBandwidth = 0.0;   // rad/s; 0: min(10, 0.1/dt)
    double driveMaxEffort = 0.0;   // N m or N; 0: unbounded
    double driveTolerance = 1e-3;  // rad or m
    bool equilibrium = false;      // start from static equilibrium instead of the given q0
  };
  // A force and moment history on a body (forces/body_load.hpp): rows [t, fx, fy, fz, mx, my, mz]
  // in the world or the body frame, at a point fixed on the body; linear between rows.
  struct Load {
    std::string name, body;
    dynamics::Vector3 point = dynamics::Vector3::Zero();  // body frame
    bool bodyFrame = false;
    std::vector<std::array<double, 7>> series;
  };
  // A quantity watched for a threshold crossing, reported as a located state event `crossed`:
  // `<joint>.q|v`, `<body>.x|y|z|roll|pitch|yaw`, `<rope>.tension|length`.
  struct Watch {
    std::string name, element, quantity;
    double threshold = 0.0;
    bool above = true;  // fires when the quantity rises above (or falls below) the threshold
  };
  // hydrostatics on a body: its hull mesh, read, checked and placed in the body frame
  struct Hull {
    std::string name, body;
    std::shared_ptr<const forces::TriangleMesh> mesh;
    bool incidentPressure = true;  // froude_krylov: nonlinear (true) or none (false: calm clipping)
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
  // hydrodynamics on a body (forces/hydro/hydrodynamics_methods.hpp): its provider, built on the
  // scene's one sea (impulse response or a time-domain method, chosen and prepared at the door)
  using HydroBuild = std::function<std::unique_ptr<forces::ForceProvider>(
      const std::string& name, const dynamics::Model& model, int body,
      std::shared_ptr<const forces::AiryWaves> sea)>;
  struct Hydrodynamics {
    std::string name, body;
    HydroBuild build;
    // (the run's end time, s) => why a run that long is not fine, one sentence each with the
    // numbers (a marched free surface's growing short waves); empty: none to check
    std::function<std::vector<std::string>(double until)> runCheck;
    // (the scene's one sea) => why the provider cannot take it (a component above the frequency
    // its response resolves), one sentence each with the numbers; empty: none to check
    std::function<std::vector<std::string>(const forces::AiryWaves& sea)> seaCheck;
    // () => the provider's own marching step and its stability limit (rankine_td: the panel step
    // against the emp limit of its free surface), for the stiffness guard and run.json; empty:
    // nothing marched at a step of its own
    std::function<forces::hydro::MarchingStep()> marchingStep = {};
  };
  // A force provider contributed by a registered reader (scene/provider_readers.hpp; a new
  // provider is its forces/ file pair and one reader function): attached at points on bodies
  // (body frame, m) or in the world, built for the system's model when the system is built and
  // evaluated after the built-in providers.
  using ProviderBuild = std::function<std::unique_ptr<forces::ForceProvider>(
      const std::string& name, const dynamics::Model& model,
      const std::vector<forces::Attachment>& at)>;
  // Bodies a provider owns (a lumped line's inner nodes, forces/lines/lumped_line_provider.hpp):
  // (its full name, its attachments' world points at the declared bodies' q0) => bodies added to
  // the system's tree after the declared ones, each with its q0 and v0. Their states are then
  // part of q and v like any body's: integrated, linearised by the stiffness guard, checkpointed.
  using ProviderBodies = std::function<std::vector<Body>(
      const std::string& name, const std::vector<dynamics::Vector3>& at_W)>;
  // The same, for bodies that depend on the scene's environment (a lumped line's net weight on
  // the scene's water density): (full name, attachments' world points, the scene's spec with its
  // environment) => bodies; used instead of bodies when set.
  using ProviderBodiesInSea = std::function<std::vector<Body>(
      const std::string& name, const std::vector<dynamics::Vector3>& at_W,
      const MechanicsSpec& environment)>;
  // The same, for a provider that needs more of the built system than its model: the bodies'
  // geometry, the ropes' paths (the collision reader); used instead of build when set.
  using ProviderBuildFromSystem = std::function<std::unique_ptr<forces::ForceProvider>(
      const std::string& name, const BuiltMechanics& mech,
      const std::vector<forces::Attachment>& at)>;
  struct ProviderSpec {
    std::string kind, name;  // kind: the mechanics key that declared it (springs, ...)
    std::vector<Point> attachments;
    ProviderBuild build;
    ProviderBodies bodies = {};  // empty: the provider owns no body
    ProviderBodiesInSea bodiesInSea = {};
    ProviderBuildFromSystem buildFromSystem = {};
    // true: when the fragments are merged, every body with a geometry becomes an attachment
    // (the scene-level `collision:`: bodies need not be listed)
    bool everyBodyWithGeometry = false;
    // true: the provider has a winch (ForceProvider::payoutWinch()) that a wire actor naming it
    // drives, like a rope's (a crane rope with mass)
    bool winch = false;
  };
  dynamics::Vector3 gravity{0.0, 0.0, -9.81};
  Settings settings;
  std::vector<ProviderSpec> providers;
  std::vector<Load> loads;
  std::vector<Watch> watches;
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
  std::vector<Hydrodynamics> hydrodynamics;
};

struct BuiltMechanics {
  dynamics::Model model;
  Eigen::VectorXd q0, v0;
  std::vector<std::string> jointNames;  // per body index (0: world, "")
  std::vector<char> hold;               // per body index: the joint starts held (brake)
  std::vector<MechanicsSpec::Rope> ropes;
  std::vector<MechanicsSpec::Equalizer> equalizers;
  std::vector<MechanicsSpec::Load> loads;
  std::vector<MechanicsSpec::Watch> watches;
  MechanicsSpec environment;  // water, waves, current, wind, hulls, flow loads, dampers, hydrodynamics (no bodies)
  std::vector<MechanicsSpec::Visual> visuals = {};          // per body index (0: world); defaulted
  std::vector<MechanicsSpec::ProviderSpec> providers = {};  // from registered readers
  // bodies whose added mass follows their draft, with their tables (added_mass_build.hpp)
  struct DraftAddedMass {
    std::string body;
    std::shared_ptr<const forces::hydro::DraftAddedMassTable> table;
  };
  std::vector<DraftAddedMass> draftAddedMass = {};
};

}  // namespace yardsim::mechanics
