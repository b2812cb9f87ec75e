#pragma once
// A lumped-mass line (MoorDyn's formulation, Hall and Goupee, Ocean Engineering 104, 2015): N
// straight segments of unstretched length l = L/N between N + 1 nodes, node 0 at the anchor end
// and node N at the fairlead end. Per segment, tension only: T = max(0, EA e + c de/dt) while
// the strain e = |r_(i+1) - r_i| / l - 1 > 0, else 0 (c the internal damping, N s, per unit
// strain rate). Per node (the half segments on either side, length l_n): net weight
// w l_n (w = (mu - rho pi d^2/4) g, N/m, down the world z), Morison drag
// 1/2 rho Cdn d l_s |u_n| u_n and 1/2 rho Cdt pi d l_s |u_t| u_t on the relative flow velocity's
// normal and tangential parts (l_s the stretched node length, the tangent q along the line),
// fluid inertia rho V [(1 + Can) a_n + (1 + Cat) a_t] of the waves' acceleration (V = pi d^2/4
// l_n), and a sea bed: a normal force (z_bed - z) kb d l_n - vz cb d l_n (>= 0) while below it,
// with Coulomb friction mu N against the horizontal velocity (linear below a regularizing
// speed). Each node's mass is mu l_n plus the added mass rho V [Can (I - q q^T) + Cat q q^T].
// Optional bending stiffness EI (lumped_line_bending.hpp): an energy EI/l (1 - cos theta) at every
// inner node, theta the angle between its two segments, with its exact gradient as node forces;
// the ends pinned (no moment). EI = 0 (the default) leaves every result as without it.
// Under a winch (a crane rope's, forces/winch.hpp) the unstretched length L(t) is the winch's and
// every segment's is l(t) = L(t)/N: the strain e = |d| / l(t) - 1, its rate u.dv / l - |d| l' / l^2
// (the damping acts on the rope's elongation beyond what the winch pays out, as the massless
// rope's), the net weight, bending, bed and fluid terms and the node masses (nodeMass()) on
// l_n(t). potentialEnergyRate() is dV/dl l' at fixed positions, the winch's power. The winch's
// minimum length must be > 0 (the masses stay positive).
// All world frame, SI units. This is the node-force evaluation as a pure function of node
// positions and velocities; lumped_line_provider.hpp makes the inner nodes bodies of the
// multibody tree (their states integrated with the rest); the end nodes' forces are what the
// attached bodies (anchor, fairlead) feel, their own weight share included.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dynamics/spatial.hpp"
#include "forces/airy_waves.hpp"
#include "forces/current_profile.hpp"
#include "forces/winch.hpp"

namespace yardsim::forces {

struct LumpedLineProperties {
  double length = 0.0;           // L, unstretched, m
  int segments = 20;             // N >= 1
  double diameter = 0.0;         // d, volume-equivalent, m
  double massPerLength = 0.0;    // mu, in air, kg/m
  double ea = 0.0;               // N
  double ei = 0.0;               // bending stiffness, N m^2 (>= 0; 0: none)
  double damping = 0.0;          // c, N s (>= 0); < 0: -c is a fraction of a segment's critical
                                 // damping l sqrt(EA mu)
  double cdn = 0.0, cdt = 0.0;   // Morison drag coefficients, normal and tangential
  double can = 0.0, cat = 0.0;   // added-mass coefficients, normal and tangential
  double waterDensity = 1025.0;  // kg/m^3
  double gravity = 9.81;         // m/s^2
  bool seabed = false;           // a flat sea bed at z = seabedZ
  double seabedZ = 0.0;          // m, world
  double bedStiffness = 0.0;     // kb, Pa/m
  double bedDamping = 0.0;       // cb, Pa s/m
  double bedFriction = 0.0;      // Coulomb coefficient
  double frictionSpeed = 1e-3;   // the friction grows linearly up to this speed, m/s (> 0)
};

class LumpedLine {
 public:
  // (properties, name, waves and current or null: still water, the winch that sets its
  // unstretched length or null: p.length throughout) => the line; throws std::invalid_argument
  // naming it for a parameter out of range or a winch that does not start at p.length or whose
  // minimum length is not > 0. waves and current must outlive it.
  LumpedLine(const LumpedLineProperties& p, std::string name, const AiryWaves* waves = nullptr,
             const CurrentField* current = nullptr, std::shared_ptr<const Winch> winch = nullptr);

  const std::string& name() const { return name_; }
  const LumpedLineProperties& properties() const { return p_; }
  int nodes() const { return p_.segments + 1; }
  double segmentLength() const { return l_; }  // l at the start, m
  // (t) => l(t) = L(t) / N under the winch (l without one), m; its rate l'(t), m/s
  double segmentLength(double t) const { return winch_ ? winch_->length(t) / p_.segments : l_; }
  double segmentLengthRate(double t) const { return winch_ ? winch_->rate(t) / p_.segments : 0.0; }
  // the winch, or null
  const Winch* winch() const { return winch_.get(); }
  double weightPerLength() const { return w_; }     // w, N/m (< 0: buoyant)
  double dampingCoefficient() const { return c_; }  // c, N s
  // (node) => its unstretched length l_n (l/2 at the ends, l inside) at the start, m
  double nodeLength(int i) const { return nodeLength(i, l_); }
  // (node, segment length l) => l/2 at the ends, l inside, m
  double nodeLength(int i, double l) const { return i == 0 || i == p_.segments ? 0.5 * l : l; }
  // b: a node's force depends on the nodes i - b .. i + b (1 without bending, 2 with EI > 0)
  int jacobianBandwidth() const { return p_.ei > 0.0 ? 2 : 1; }

  // (r, v: 3 x nodes, world, m and m/s; t, s) => f: the net force on every node (segments,
  // weight, drag, fluid inertia, bed), N, and the tension of every segment, N. f and tension
  // must be sized 3 x nodes() and segments. Allocation-free.
  void nodeForces(const Eigen::Matrix3Xd& r, const Eigen::Matrix3Xd& v, double t,
                  Eigen::Matrix3Xd& f, Eigen::VectorXd& tension) const;
  // (r, t) => every node's 3x3 mass, structural plus added, on its length l_n(t) (the ends' half
  // segments included), kg; m sized nodes(). Allocation-free.
  void nodeMass(const Eigen::Matrix3Xd& r, double t, std::vector<dynamics::Matrix3>& m) const;
  // (r, t) => strain energy of the taut segments + bending + net weight w l_n z + bed springs, J
  double potentialEnergy(const Eigen::Matrix3Xd& r, double t) const;
  // (r, t) => dV/dt at fixed r: dV/dl l'(t), the power the winch puts into the line, W (0 without
  // a winch or while it stands)
  double potentialEnergyRate(const Eigen::Matrix3Xd& r, double t) const;
  // (r, t) => f = -dV/dr, the conservative part of nodeForces (the segments' EA e, bending, the net
  // weight, the bed springs), N, sized 3 x nodes(); nodeForces minus it is what dissipates or
  // comes from the flow (internal and bed damping, friction, drag, fluid inertia).
  // Allocation-free.
  void conservativeForces(const Eigen::Matrix3Xd& r, double t, Eigen::Matrix3Xd& f) const;
  // (r, v, t) => per node i the 3x3 blocks df_i/dr_j (N/m) and df_i/dv_j (N s/m) of nodeForces
  // for j = i - b .. i + b at [(2 b + 1) i + j - i + b] (zero past the ends), b =
  // jacobianBandwidth() (1: [3 i + j - i + 1]), both sized (2 b + 1) nodes(): the taut segments'
  // EA/l u u^T + T/|d| (I - u u^T) with their damping's terms (zero while slack), the bending's
  // Hessian (lumped_line_bending.hpp), the drag's velocity terms, the bed's spring, damping and
  // friction. Left out: the
  // drag's and the fluid inertia's dependence on the positions (the flow field, the tangent,
  // the stretched length), small beside EA/l. Returns a signature of the switches (taut
  // segments, nodes on the bed, friction below its regularising speed): it changes when one
  // does. Allocation-free.
  std::uint64_t forceJacobian(const Eigen::Matrix3Xd& r, const Eigen::Matrix3Xd& v, double t,
                              std::vector<dynamics::Matrix3>& dfdr,
                              std::vector<dynamics::Matrix3>& dfdv) const;

 private:
  // (r, node) => unit tangent: along the chord of its neighbours (the end segment at an end)
  dynamics::Vector3 tangent(const Eigen::Matrix3Xd& r, int i) const;

  LumpedLineProperties p_;
  std::string name_;
  const AiryWaves* waves_;
  const CurrentField* current_;
  std::shared_ptr<const Winch> winch_;
  double l_ = 0.0, w_ = 0.0, c_ = 0.0, area_ = 0.0;
};

}  // namespace yardsim::forces
