#pragma once
// The multibody models timed side by side with RBDL and Pinocchio, described once, neutrally, and
// built by each library's own API (yardsim_kernel.cpp, rbdl_kernel.cpp, pinocchio_kernel.cpp):
// - chain(N): bench/multibody's planar chain, N revolute links (1 kg, 1 m uniform rods along x,
//   hinges about y, gravity along -z);
// - tree(N): a branched floating-base tree, the shape of yardsim's scenes (a block held by a
//   crane's ropes and hooks): a free-joint root (1000 kg box) with four branches of (N - 1) / 4
//   bodies each whose joints alternate revolute and prismatic, axes cycling x, y, z.
// Units SI; every frame offset is in the parent body frame; inertias about the centre of mass.
#include <Eigen/Core>
#include <string>
#include <vector>

namespace yardsim::bench::peers {

enum class JointKind { Free, Revolute, Prismatic };

struct BodySpec {
  int parent = -1;  ///< index in the spec, -1 for the world
  JointKind kind = JointKind::Revolute;
  int axis = 1;  ///< 0, 1, 2: x, y, z of the joint frame
  Eigen::Vector3d offset =
      Eigen::Vector3d::Zero();  ///< joint frame origin in the parent body frame, m
  double mass = 1.0;            ///< kg
  Eigen::Vector3d com = Eigen::Vector3d::Zero();  ///< centre of mass in the body frame, m
  Eigen::Vector3d inertia =
      Eigen::Vector3d::Ones();  ///< principal inertia about the com (body axes), kg m^2
};

// (N) => the planar chain of N rods
inline std::vector<BodySpec> chain(int n) {
  std::vector<BodySpec> s;
  for (int i = 0; i < n; ++i) {
    const double t = 1.0 / 12.0;  // m L^2 / 12 of a 1 kg, 1 m rod
    s.push_back({i - 1, JointKind::Revolute, 1, Eigen::Vector3d(i == 0 ? 0.0 : 1.0, 0.0, 0.0), 1.0,
                 Eigen::Vector3d(0.5, 0.0, 0.0), Eigen::Vector3d(1e-6 * t, t, t)});
  }
  return s;
}

// (N >= 5) => the free-floating root and four branches of (N - 1) / 4 bodies
inline std::vector<BodySpec> tree(int n) {
  std::vector<BodySpec> s;
  s.push_back({-1, JointKind::Free, 0, Eigen::Vector3d::Zero(), 1000.0, Eigen::Vector3d::Zero(),
               Eigen::Vector3d(1000.0, 2000.0, 2500.0)});
  const int k = (n - 1) / 4;
  const double corner[4][2] = {{5, 3}, {-5, 3}, {-5, -3}, {5, -3}};
  for (int b = 0; b < 4; ++b) {
    for (int j = 0; j < k; ++j) {
      const int parent = j == 0 ? 0 : static_cast<int>(s.size()) - 1;
      const Eigen::Vector3d off = j == 0 ? Eigen::Vector3d(corner[b][0], corner[b][1], 1.0)
                                         : Eigen::Vector3d(0.1, 0.2, 2.0);
      s.push_back({parent, j % 2 == 0 ? JointKind::Revolute : JointKind::Prismatic, j % 3, off,
                   50.0, Eigen::Vector3d(0.05, -0.02, 1.0), Eigen::Vector3d(20.0, 21.0, 2.0)});
    }
  }
  return s;
}

// ("chain" | "tree", N) => the model's spec; throws std::invalid_argument otherwise
std::vector<BodySpec> modelSpec(const std::string& name, int n);

}  // namespace yardsim::bench::peers
