// The largest mode of a structured system (mechanics/largest_mode.hpp: the Jacobian on its pattern
// by colours, Arnoldi on it) against an independent dense computation: every column of J by
// central differences and every eigenvalue (Eigen's EigenSolver), on a buoy moored by four lumped
// chains lying on the sea bed (bed springs and damping, internal damping, drag) and hanging free.
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <string>

#include <Eigen/Eigenvalues>

#include "dynamics/configuration.hpp"
#include "mechanics/build.hpp"
#include "mechanics/data.hpp"
#include "mechanics/largest_mode.hpp"
#include "mechanics/set_points.hpp"
#include "mechanics/stage.hpp"
#include "mechanics/system.hpp"
#include "scene/mechanical_systems.hpp"
#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

namespace {

// (segments, extra line keys) => a 200 t buoy on a surge-sway slider, four chains 290 m out, 39 m
// down
std::string moored(int segments, const std::string& extra) {
  std::string s = R"(schema_version: 1
integrator: {method: hht, dt: 0.05, stiffness_check: off}
mechanics:
  gravity: [0, 0, -9.81]
  bodies:
    slide: {parent: world, joint: {type: prismatic, axis: [1, 0, 0]}, mass: 1.0, inertia: [1, 1, 1]}
    buoy: {parent: slide, joint: {type: prismatic, axis: [0, 1, 0]}, placement: {xyz: [0, 0, 39]},
           mass: 2.0e5, inertia: [1, 1, 1]}
  mooring:
)";
  const char* anchors[] = {"[290, 0, 0]", "[0, 290, 0]", "[-290, 0, 0]", "[0, -290, 0]"};
  for (int k = 0; k < 4; ++k)
    s += "    line" + std::to_string(k) + ": {model: lumped, anchor: " + anchors[k] +
         ", fairlead: {body: buoy}, length: 314, EA: 1.2e9, mass: 282.21, diameter: 0.216, "
         "segments: " +
         std::to_string(segments) + extra + "}\n";
  return s + "until: 1\n";
}

}  // namespace

TEST_CASE(
    "largest mode of moored lumped chains: Arnoldi on the coloured Jacobian equals the dense "
    "eigen-solve") {
  // (on the bed: its damping's real eigenvalue leads; off it: the chains' axial modes, complex
  // pairs in a cluster at the top)
  // (and with bending stiffness EI 1e12 N m^2 off the bed: 16 EI / l^3 beside 4 EA / l, its
  // zigzag bending mode among the top ones; the pattern two nodes wide)
  for (const std::string extra : {"", ", seabed: false", ", seabed: false, EI: 1.0e12"})
    for (int segments : {8, 16}) {
      testing::SceneDir dir;
      auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", moored(segments, extra)));
      REQUIRE(scene->systems.size() == 1);
      const mechanics::BuiltMechanics mech = mechanics::buildMechanics(scene->systems[0]->spec);
      const mechanics::System system(mech, {}, "test");
      mechanics::Data data(system);
      const auto& model = mech.model;
      mechanics::SetPoints held{
          std::vector<mechanics::JointDrive>(static_cast<std::size_t>(model.nbodies)),
          std::vector<mechanics::ActorLoad>(static_cast<std::size_t>(model.nbodies)),
          std::vector<mechanics::WinchJob>(system.ropes().size())};
      data.setPoints = &held;
      mechanics::connectStage(system, data);
      const dynamics::JacobianPattern* pattern = data.kernel.jacobianPattern();
      REQUIRE(pattern != nullptr);
      const double step = 1e-7;
      const mechanics::LargestMode mode =
          mechanics::largestMode(data.kernel, model, mech.q0, mech.v0, *pattern, step);
      // (independent) => J dense, one central difference per dof, every eigenvalue
      const int nv = model.nv;
      Eigen::MatrixXd J = Eigen::MatrixXd::Zero(2 * nv, 2 * nv);
      J.topRightCorner(nv, nv).setIdentity();
      Eigen::VectorXd q(model.nq), v(nv), ap(nv), am(nv), d(nv);
      for (int j = 0; j < nv; ++j) {
        d.setZero();
        d[j] = step;
        dynamics::integrate(model, mech.q0, d, 1.0, q);
        data.kernel.acceleration(0.0, q, mech.v0, ap);
        dynamics::integrate(model, mech.q0, d, -1.0, q);
        data.kernel.acceleration(0.0, q, mech.v0, am);
        J.block(nv, j, nv, 1) = (ap - am) / (2 * step);
        v = mech.v0;
        v[j] += step;
        data.kernel.acceleration(0.0, mech.q0, v, ap);
        v[j] -= 2 * step;
        data.kernel.acceleration(0.0, mech.q0, v, am);
        J.block(nv, nv + j, nv, 1) = (ap - am) / (2 * step);
      }
      const Eigen::EigenSolver<Eigen::MatrixXd> eig(J, false);
      Eigen::Index top = 0;
      eig.eigenvalues().cwiseAbs().maxCoeff(&top);
      const std::complex<double> dense = eig.eigenvalues()[top];
      INFO("'" << extra << "' " << segments << " segments, nv " << nv << ": Arnoldi " << mode.lambda
               << " (residual " << mode.residual << "), dense " << dense);
      CHECK(std::abs(dense) > 50.0);  // a stiff mode, not a slack line's zero
      CHECK(std::abs(mode.lambda) == Approx(std::abs(dense)).epsilon(1e-3));
      CHECK(-mode.lambda.real() / std::abs(mode.lambda) ==
            Approx(-dense.real() / std::abs(dense)).margin(1e-2));
      CHECK(mode.residual <= 1e-3);
      // (its mode) => moves a node of a line, not the buoy
      Eigen::Index dof = 0;
      mode.shape.cwiseAbs().maxCoeff(&dof);
      CHECK(
          model.names[static_cast<std::size_t>(model.dofBody[static_cast<std::size_t>(dof)])].find(
              ".node") != std::string::npos);
    }
}
