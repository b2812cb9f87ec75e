// The clipped hull against closed forms: a box barge and a vertical cylinder at several drafts
// (exact for the polyhedra, second-order convergence to the round cylinder), a box heeled by 5
// and 20 degrees against the wall-sided formula, sphere caps, fully submerged and dry hulls, and
// the Froude-Krylov heave force of a small box in a long wave (Smith effect e^{-kT}), and the
// Froude-Krylov force of a small submerged box against the particle acceleration.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "dynamics/rotation.hpp"
#include "forces/geometry/primitive_meshes.hpp"
#include "forces/geometry/submerged_mesh.hpp"

using namespace yardsim;
using namespace yardsim::forces;
using dynamics::Transform;
using dynamics::Vector3;

namespace {
constexpr double kRho = 1025.0, kG = 9.81;
const AiryWaves calmSea{WaterProperties{kRho, kG, 0.0}};
double rel(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }
// (the first n wetted pieces kept in ws, pressure(q)) => the edge-midpoint rule written out,
// piece by piece and side by side: -sum p(q) / 3 S and -sum p(q) / 3 q x S
template <class Pressure>
std::pair<Vector3, Vector3> midpointRule(const SubmergedWorkspace& ws, int n, Pressure pressure) {
  Vector3 F = Vector3::Zero(), M = Vector3::Zero();
  for (int i = 0; i < n; ++i) {
    const auto& [a, b, c] = ws.wet[static_cast<std::size_t>(i)];
    const Vector3 S = 0.5 * (b - a).cross(c - a);
    for (const Vector3& q :
         {Vector3(0.5 * (a + b)), Vector3(0.5 * (b + c)), Vector3(0.5 * (c + a))}) {
      const double p = pressure(q);
      F -= p / 3.0 * S;
      M -= p / 3.0 * q.cross(S);
    }
  }
  return {F, M};
}
}  // namespace

TEST_CASE("box barge at several drafts: volume, buoyancy, waterplane exact to round-off") {
  const double L = 60.0, B = 20.0, D = 6.0;
  const TriangleMesh hull = boxMesh(Vector3(L, B, D), 6, 4, 3);  // body origin at mid-depth
  SubmergedWorkspace ws(hull);
  for (double T : {0.5, 2.0, 3.7, 5.5}) {
    for (double yaw : {0.0, 0.7}) {
      INFO("draft " << T << " yaw " << yaw);
      const Vector3 at(13.0, -4.0, D / 2 - T);
      const Transform X{dynamics::axisRotation(Vector3::UnitZ(), yaw), at};
      const SubmergedProperties p = integrateSubmerged(hull, X, calmSea, 0.0, ws, true);
      const double V = L * B * T;
      CHECK(rel(p.volume, V) < 1e-13);
      CHECK((p.centreOfBuoyancy - Vector3(at.x(), at.y(), -T / 2)).norm() < 1e-12 * L);
      CHECK(rel(p.waterplaneArea, L * B) < 1e-13);
      CHECK((p.waterplaneCentroid - at.head<2>()).norm() < 1e-12 * L);
      // second moments in the body axes: I_L = B L^3/12 along x, I_T = L B^3/12 across
      const Eigen::Matrix2d R = X.R.topLeftCorner<2, 2>();
      const Eigen::Matrix2d J_B = R.transpose() * p.waterplaneInertia * R;
      CHECK(rel(J_B(0, 0), B * L * L * L / 12) < 1e-12);
      CHECK(rel(J_B(1, 1), L * B * B * B / 12) < 1e-12);
      CHECK(std::abs(J_B(0, 1)) < 1e-12 * J_B(0, 0));
      CHECK(rel(p.wettedArea, L * B + 2 * (L + B) * T) < 1e-13);
      CHECK((p.force - Vector3(0, 0, kRho * kG * V)).norm() < 1e-12 * kRho * kG * V);
      CHECK((p.moment - p.centreOfBuoyancy.cross(p.force)).norm() < 1e-12 * kRho * kG * V * L);
      // the wetted pieces kept: their area adds up
      double area = 0.0;
      for (int i = 0; i < p.wetTriangles; ++i) {
        const auto& t = ws.wet[static_cast<std::size_t>(i)];
        area += 0.5 * (t[1] - t[0]).cross(t[2] - t[0]).norm();
        for (const Vector3& c : t) CHECK(c.z() <= 1e-12);
      }
      CHECK(rel(area, p.wettedArea) < 1e-13);
    }
  }
}

TEST_CASE("vertical cylinder: exact for the polygon, second order towards the circle") {
  const double R = 5.0, T = 3.0;
  double prevV = 0.0, prevI = 0.0, prevB = 0.0;
  for (int n : {24, 48, 96}) {
    const TriangleMesh hull = cylinderMesh(R, -8.0, 4.0, n, 3);
    SubmergedWorkspace ws(hull);
    for (double draft : {1.0, T, 7.5}) {
      const SubmergedProperties p = integrateSubmerged(hull, Transform::translation(Vector3(0, 0, 8.0 - draft)),
                                                       calmSea, 0.0, ws);
      // (regular n-gon of circumradius R) => area n R^2 sin(2 pi/n)/2, I = n R^4 sin(2pi/n)(2 + cos(2pi/n))/24
      const double s = std::sin(2 * M_PI / n), c = std::cos(2 * M_PI / n);
      const double A = 0.5 * n * R * R * s, I = n * std::pow(R, 4) * s * (2 + c) / 24;
      CHECK(rel(p.volume, A * draft) < 1e-13);
      CHECK(std::abs(p.centreOfBuoyancy.z() + draft / 2) < 1e-12);
      CHECK(rel(p.waterplaneArea, A) < 1e-13);
      CHECK(rel(p.waterplaneInertia(0, 0), I) < 1e-12);
      CHECK(rel(p.waterplaneInertia(1, 1), I) < 1e-12);
      CHECK(rel(p.force.z(), kRho * kG * A * draft) < 1e-13);
    }
    const SubmergedProperties p = integrateSubmerged(hull, Transform::translation(Vector3(0, 0, 8.0 - T)),
                                                     calmSea, 0.0, ws);
    const double eV = std::abs(p.volume - M_PI * R * R * T);
    const double eI = std::abs(p.waterplaneInertia(0, 0) - M_PI * std::pow(R, 4) / 4);
    const double eB = std::abs(p.force.z() - kRho * kG * M_PI * R * R * T);
    if (prevV > 0) {
      CHECK(std::log2(prevV / eV) == Approx(2.0).margin(0.02));
      CHECK(std::log2(prevI / eI) == Approx(2.0).margin(0.02));
      CHECK(std::log2(prevB / eB) == Approx(2.0).margin(0.02));
    }
    prevV = eV;
    prevI = eI;
    prevB = eB;
  }
}

TEST_CASE("box heeled by 5 and 20 degrees: righting arm of the wall-sided formula") {
  // heeled about the longitudinal axis through the waterplane centre: the emerged and immersed
  // wedges are equal, V = L B T; while neither the deck edge nor the bilge crosses the water,
  // GZ = sin(phi) (GM + BM tan^2(phi) / 2), GM = KB + BM - KG, BM = B^2 / (12 T)
  const double L = 40.0, B = 12.0, D = 8.0, T = 4.0, KG = 5.0;
  const TriangleMesh hull = boxMesh(Vector3(L, B, D), 4, 3, 2);  // origin at mid-depth
  SubmergedWorkspace ws(hull);
  const double BM = B * B / (12 * T), GM = T / 2 + BM - KG;
  for (double deg : {5.0, 20.0}) {
    INFO(deg << " deg");
    const double phi = deg * M_PI / 180;
    REQUIRE(B / 2 * std::tan(phi) < std::min(T, D - T));  // wall-sided range
    // body point (0, 0, -D/2 + T) (the waterline centre) stays at the origin
    const dynamics::Matrix3 Rx = dynamics::axisRotation(Vector3::UnitX(), phi);
    const Transform X{Rx, -(Rx * Vector3(0, 0, -D / 2 + T))};
    const SubmergedProperties p = integrateSubmerged(hull, X, calmSea, 0.0, ws);
    CHECK(rel(p.volume, L * B * T) < 1e-12);
    const Vector3 G = X.actPoint(Vector3(0, 0, -D / 2 + KG));
    const Vector3 M_G = p.moment - G.cross(p.force);  // about G
    const double GZ = -M_G.x() / p.force.z();          // righting arm (> 0 restores)
    CHECK(rel(GZ, std::sin(phi) * (GM + 0.5 * BM * std::tan(phi) * std::tan(phi))) < 1e-11);
    CHECK(GZ > 0.0);
  }
}

TEST_CASE("sphere at several immersions: spherical-cap volume, second order in the mesh") {
  const double R = 3.0;
  for (double h : {0.8, 3.0, 4.5}) {
    INFO("immersion " << h);
    const double Vcap = M_PI * h * h * (3 * R - h) / 3, Awp = M_PI * (2 * R * h - h * h);
    double firstV = 0.0, firstA = 0.0, eV = 0.0, eA = 0.0;
    for (int n : {32, 64, 128}) {
      const TriangleMesh hull = sphereMesh(R, n, 2 * n);
      SubmergedWorkspace ws(hull);
      const SubmergedProperties p =
          integrateSubmerged(hull, Transform::translation(Vector3(0, 0, R - h)), calmSea, 0.0, ws);
      eV = std::abs(p.volume - Vcap);
      eA = std::abs(p.waterplaneArea - Awp);
      CHECK(eV < 0.01 * Vcap);
      if (n == 32) {
        firstV = eV;
        firstA = eA;
      }
      // centre of buoyancy of a cap: 3 (2R - h)^2 / (4 (3R - h)) below the sphere's centre
      const double zc = -3 * (2 * R - h) * (2 * R - h) / (4 * (3 * R - h));
      CHECK(p.centreOfBuoyancy.z() - (R - h) == Approx(zc).margin(0.01 * R));
    }
    // (32 -> 128 bands: the mesh size / 4) => errors / 16 (the waterline crossing the rings makes
    // single halvings noisy)
    CHECK(std::log2(firstV / eV) / 2 == Approx(2.0).margin(0.2));
    CHECK(std::log2(firstA / eA) / 2 == Approx(2.0).margin(0.2));
  }
}

TEST_CASE("fully submerged, dry and upside-down hulls") {
  const TriangleMesh hull = boxMesh(Vector3(4, 2, 1), 2, 2, 2);
  SubmergedWorkspace ws(hull);
  const SubmergedProperties under = integrateSubmerged(hull, Transform::translation(Vector3(1, 2, -10)), calmSea, 0, ws);
  CHECK(rel(under.volume, 8.0) < 1e-13);
  CHECK(std::abs(under.waterplaneArea) < 1e-12);
  CHECK(rel(under.force.z(), kRho * kG * 8.0) < 1e-12);
  CHECK(std::abs(under.force.x()) + std::abs(under.force.y()) < 1e-8);
  CHECK((under.centreOfBuoyancy - Vector3(1, 2, -10)).norm() < 1e-12);
  const SubmergedProperties dry = integrateSubmerged(hull, Transform::translation(Vector3(0, 0, 0.5)), calmSea, 0, ws);
  CHECK(dry.volume == 0.0);
  CHECK(dry.force.norm() == 0.0);
  CHECK(dry.wettedArea == 0.0);
  // capsized: turned over about x, the same draft gives the same volume and force
  const Transform flipped{dynamics::axisRotation(Vector3::UnitX(), M_PI), Vector3(0, 0, 0.2)};
  const SubmergedProperties up = integrateSubmerged(hull, Transform::translation(Vector3(0, 0, 0.2)), calmSea, 0, ws);
  const SubmergedProperties over = integrateSubmerged(hull, flipped, calmSea, 0, ws);
  CHECK(rel(over.volume, up.volume) < 1e-12);
  CHECK(rel(over.force.z(), up.force.z()) < 1e-12);
}

TEST_CASE("a small box in a long wave feels the Froude-Krylov heave force rho g A (T + a e^{-kT} cos)") {
  const double a = 0.5, T = 2.0;
  const AiryWaves sea(WaterProperties{kRho, kG, 0.0}, {{2 * a, 12.0, 0.0, 0.0}});
  const double k = sea.wavenumber(0);
  const TriangleMesh hull = boxMesh(Vector3(0.5, 0.5, 6.0), 1, 1, 4);  // tiny against L = 225 m
  SubmergedWorkspace ws(hull);
  const double A = 0.25;
  for (double t : {0.0, 2.0, 3.0, 5.0, 7.5}) {
    INFO("t = " << t);
    const SubmergedProperties p = integrateSubmerged(hull, Transform::translation(Vector3(0, 0, 3.0 - T)), sea, t, ws);
    const double wave = a * std::exp(-k * T) * std::cos(-2 * M_PI / 12.0 * t);
    // second-order (stretching) terms are O(k a) of the wave part
    CHECK(p.force.z() == Approx(kRho * kG * A * (T + wave)).margin(kRho * kG * A * a * 0.05));
    CHECK(std::abs(p.force.z() - kRho * kG * A * T) > 0.5 * kRho * kG * A * std::abs(wave) - 1e-9);
  }
}

TEST_CASE("a small submerged box feels the Froude-Krylov force rho V (g z + du/dt) of the wave") {
  // (-grad p = rho g z_hat + rho du/dt in linear theory) => the pressure integral over a body
  // small against the wave length equals rho V times the particle acceleration at its centre
  const AiryWaves sea(WaterProperties{kRho, kG, 0.0, 60.0, 0.0}, {{1.0, 8.0, 0.4, 0.0}});
  const TriangleMesh hull = boxMesh(Vector3(1.0, 1.0, 1.0), 2, 2, 2);
  SubmergedWorkspace ws(hull);
  const Vector3 c(3.0, -2.0, -6.0);
  double biggest = 0.0;
  for (double t : {0.0, 1.0, 2.5, 4.0, 6.5}) {
    INFO("t = " << t);
    const SubmergedProperties p = integrateSubmerged(hull, Transform::translation(c), sea, t, ws);
    const Vector3 expected = kRho * 1.0 * (Vector3(0, 0, kG) + sea.acceleration(c, t));
    const Vector3 wave = kRho * sea.acceleration(c, t);
    CHECK((p.force - expected).norm() < 0.02 * wave.norm() + 1e-9 * kRho * kG);
    biggest = std::max(biggest, wave.head<2>().norm());
  }
  CHECK(biggest > 50.0);  // the horizontal wave force is there to be checked (N)
}

TEST_CASE(
    "the force-only integrals give the same force and moment, bit for bit, and nothing else") {
  // (a heeled, trimmed box in a wave, at several times) => SubmergedIntegrals::Force's force and
  // moment equal All's exactly; its volume, waterplane and wetted area are left zero
  const AiryWaves sea(WaterProperties{kRho, kG, 0.0, 40.0, 0.0}, {{1.5, 7.0, 1.2, 0.3}});
  const TriangleMesh hull = boxMesh(Vector3(20.0, 8.0, 4.0), 6, 3, 2);
  SubmergedWorkspace ws(hull);
  Transform X = Transform::translation(Vector3(1.0, -2.0, 0.5));
  X.R = (Eigen::AngleAxisd(0.2, Vector3::UnitX()) * Eigen::AngleAxisd(-0.05, Vector3::UnitY()))
            .toRotationMatrix();
  for (double t : {0.0, 1.7, 4.2}) {
    INFO("t = " << t);
    const SubmergedProperties all = integrateSubmerged(hull, X, sea, t, ws);
    const SubmergedProperties f =
        integrateSubmerged(hull, X, sea, t, ws, false, SubmergedIntegrals::Force);
    CHECK(all.volume > 0.0);
    CHECK(f.force == all.force);
    CHECK(f.moment == all.moment);
    CHECK(f.volume == 0.0);
    CHECK(f.waterplaneArea == 0.0);
    CHECK(f.wettedArea == 0.0);
  }
}

TEST_CASE(
    "the force-only integrals equal every integral's force and moment on random poses and seas") {
  // (random poses of a box, random seas of one to three components, times before, during and
  // after the ramp) => SubmergedIntegrals::Force's force and moment bit for bit All's
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const TriangleMesh hull = boxMesh(Vector3(20.0, 8.0, 4.0), 6, 3, 2);
  int wet = 0;
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<WaveComponent> waves;
    const int components = 1 + trial % 3;
    for (int i = 0; i < components; ++i)
      waves.push_back(
          {0.3 + 1.2 * u(rng), 4.0 + 8.0 * u(rng), 2.0 * M_PI * u(rng), 2.0 * M_PI * u(rng)});
    const AiryWaves sea(WaterProperties{kRho, kG, 0.3, 30.0 + 100.0 * u(rng), 4.0, 2.0}, waves);
    SubmergedWorkspace ws(hull, sea.size());
    Transform X =
        Transform::translation(Vector3(10.0 * u(rng), -10.0 * u(rng), 4.0 - 8.0 * u(rng)));
    X.R = (Eigen::AngleAxisd(2.0 * M_PI * u(rng), Vector3::UnitZ()) *
           Eigen::AngleAxisd(0.8 * (u(rng) - 0.5), Vector3::UnitY()) *
           Eigen::AngleAxisd(3.0 * (u(rng) - 0.5), Vector3::UnitX()))
              .toRotationMatrix();
    const double t = 8.0 * u(rng);
    INFO("trial " << trial << ", t = " << t);
    const SubmergedProperties all = integrateSubmerged(hull, X, sea, t, ws);
    const SubmergedProperties f =
        integrateSubmerged(hull, X, sea, t, ws, false, SubmergedIntegrals::Force);
    CHECK(f.force == all.force);
    CHECK(f.moment == all.moment);
    if (all.volume > 0.0 && all.volume < 20.0 * 8.0 * 4.0 - 1e-9) ++wet;
  }
  CHECK(wet > 20);  // most poses cut the hull at the surface
}

TEST_CASE(
    "in waves a mesh edge that crosses the surface does so at one point for both its triangles") {
  // (a heeled box in a two-component sea, the wetted pieces kept) => the distinct crossing points
  // (corners of the pieces that are not the hull's corners) are as many as the mesh edges whose
  // ends lie on either side of the surface: each edge's point the same double vector in the two
  // triangles on it, so its side to the wet corner takes one pressure
  const AiryWaves sea(WaterProperties{kRho, kG, 0.0, 50.0, 0.0},
                      {{1.0, 5.0, 0.7, 0.3}, {0.4, 6.0, -1.0, 2.0}});
  const TriangleMesh hull = boxMesh(Vector3(20.0, 8.0, 4.0), 6, 3, 2);
  SubmergedWorkspace ws(hull, sea.size());
  Transform X = Transform::translation(Vector3(1.0, -2.0, 0.3));
  X.R = Eigen::AngleAxisd(0.15, Vector3::UnitX()).toRotationMatrix();
  for (double t : {0.4, 2.9}) {
    INFO("t = " << t);
    const SubmergedProperties p = integrateSubmerged(hull, X, sea, t, ws, true);
    // (the hull's corners in the world, their depth) => the crossed mesh edges
    std::set<std::array<double, 3>> corners, crossings;
    std::set<std::pair<int, int>> crossed;
    for (const Vector3& v : hull.vertices) {
      const Vector3 w = X.actPoint(v);
      corners.insert({w.x(), w.y(), w.z()});
    }
    for (const auto& tri : hull.triangles)
      for (int e = 0; e < 3; ++e) {
        const int i = tri[static_cast<std::size_t>(e)],
                  j = tri[static_cast<std::size_t>((e + 1) % 3)];
        const auto depth = [&](int k) {
          const Vector3 w = X.actPoint(hull.vertices[static_cast<std::size_t>(k)]);
          return sea.elevation(w.x(), w.y(), t) - w.z();
        };
        const double di = depth(i), dj = depth(j);
        CHECK(std::abs(di) > 1e-9);  // (no corner on the surface to round-off: the count is sharp)
        if ((di > 0.0) != (dj > 0.0)) crossed.insert({std::min(i, j), std::max(i, j)});
      }
    for (int k = 0; k < p.wetTriangles; ++k)
      for (const Vector3& c : ws.wet[static_cast<std::size_t>(k)])
        if (!corners.count({c.x(), c.y(), c.z()})) crossings.insert({c.x(), c.y(), c.z()});
    CHECK(crossed.size() > 10);
    CHECK(crossings.size() == crossed.size());
  }
}

TEST_CASE(
    "in a short wave the midpoints' pressure from the corners equals the pressure evaluated "
    "there") {
  // (a heeled box, deep and partly wet, in a wave about as long as the box, so the phase changes
  // by up to 0.8 rad along an edge) => the pressure force and moment of integrateSubmerged equal
  // the same edge-midpoint rule summed here with AiryWaves::pressure at each midpoint, to round-off
  const AiryWaves sea(WaterProperties{kRho, kG, 0.0, 50.0, 0.0},
                      {{1.0, 4.0, 0.7, 0.3}, {0.4, 6.0, -1.0, 2.0}});
  const TriangleMesh hull = boxMesh(Vector3(20.0, 8.0, 4.0), 6, 3, 2);
  SubmergedWorkspace ws(hull);
  for (double z : {-6.0, 0.5}) {
    Transform X = Transform::translation(Vector3(1.0, -2.0, z));
    X.R = Eigen::AngleAxisd(0.1, Vector3::UnitX()).toRotationMatrix();
    for (double t : {0.0, 1.3}) {
      INFO("z = " << z << " t = " << t);
      const SubmergedProperties got = integrateSubmerged(hull, X, sea, t, ws, true);
      // (the wetted pieces it kept) => sum over each piece's sides of -p(midpoint) / 3 S
      const auto [F, M] =
          midpointRule(ws, got.wetTriangles, [&](const Vector3& q) { return sea.pressure(q, t); });
      CHECK(got.wetTriangles > 0);
      CHECK((got.force - F).norm() < 1e-10 * F.norm());
      CHECK((got.moment - M).norm() < 1e-10 * (M.norm() + 20.0 * F.norm()));
    }
  }
}

TEST_CASE(
    "in waves the corners above the crests wait for a crossing, and the rest clip as before") {
  // (a box whose top row is above the highest crest the two-component sea reaches (ramp
  // included), whose middle row lies between the level and that crest, heeled, at times during
  // and after the ramp) => its wetted pieces' hull corners are the corners below the surface
  // (depth from AiryWaves::elevation here), and their crossing points those of the mesh edges
  // between a wet and a dry corner, interpolated from the edge's end with the lower number at
  // these depths: the deferred top corners' depths are the surface's, and no middle corner wet
  // under a crest (above the first component's alone) is taken for dry
  const AiryWaves sea(WaterProperties{kRho, kG, 0.0, 40.0, 4.0, 0.0},
                      {{1.0, 5.0, 0.4, 0.3}, {0.4, 6.0, -0.8, 2.0}});
  const TriangleMesh hull = boxMesh(Vector3(20.0, 8.0, 1.9), 6, 3, 2);  // rows z = -0.95, 0, 0.95
  SubmergedWorkspace ws(hull, sea.size());
  Transform X = Transform::translation(Vector3(2.0, -1.0, 0.45));
  X.R = Eigen::AngleAxisd(0.05, Vector3::UnitX()).toRotationMatrix();
  // (middle corners wet above 0.5 r, the first component's crest, and below it) => counts
  int highWet = 0, lowWet = 0;
  for (double t = 1.0; t < 30.0; t += 0.25) {
    INFO("t = " << t);
    const double r = sea.ramp(t);
    const SubmergedProperties p = integrateSubmerged(hull, X, sea, t, ws, true);
    std::vector<Vector3> w;
    std::vector<double> d;
    std::set<std::array<double, 3>> wetCorners, pieceCorners, pieceCrossings;
    for (const Vector3& v : hull.vertices) {
      w.push_back(X.actPoint(v));
      d.push_back(sea.elevation(w.back().x(), w.back().y(), t) - w.back().z());
      CHECK(std::abs(d.back()) > 1e-9);  // (no corner on the surface to round-off)
      if (d.back() > 0.0) wetCorners.insert({w.back().x(), w.back().y(), w.back().z()});
      if (d.back() > 0.0 && std::abs(v.z()) < 0.1) ++(w.back().z() > 0.5 * r ? highWet : lowWet);
    }
    // (mesh edges between a wet and a dry corner) => their crossing points
    std::vector<Vector3> expected;
    std::set<std::pair<int, int>> crossed;
    for (const auto& tri : hull.triangles)
      for (std::size_t e = 0; e < 3; ++e) {
        const int i = std::min(tri[e], tri[(e + 1) % 3]), j = std::max(tri[e], tri[(e + 1) % 3]);
        const auto a = static_cast<std::size_t>(i), b = static_cast<std::size_t>(j);
        if ((d[a] > 0.0) != (d[b] > 0.0) && crossed.insert({i, j}).second)
          expected.push_back(w[a] + d[a] / (d[a] - d[b]) * (w[b] - w[a]));
      }
    for (int k = 0; k < p.wetTriangles; ++k)
      for (const Vector3& c : ws.wet[static_cast<std::size_t>(k)])
        (wetCorners.count({c.x(), c.y(), c.z()}) ? pieceCorners : pieceCrossings)
            .insert({c.x(), c.y(), c.z()});
    CHECK(pieceCorners == wetCorners);
    CHECK(pieceCrossings.size() == expected.size());
    for (const auto& c : pieceCrossings) {
      double nearest = INFINITY;
      for (const Vector3& e : expected)
        nearest = std::min(nearest, (e - Vector3(c[0], c[1], c[2])).norm());
      CHECK(nearest < 1e-9);
    }
  }
  CHECK(highWet > 0);
  CHECK(lowWet > 0);
}

TEST_CASE(
    "in calm water the force and moment are the midpoint rule of rho g (level - z), bit for bit") {
  // (a heeled box across the level of a calm sea and of a wavy one before its waves start, the
  // wetted pieces kept) => the force and moment equal -sum p(q) / 3 S and -sum p(q) / 3 q x S
  // over the pieces' side midpoints in their order, p = rho g (level - z) below the level, to the
  // last bit: calm water's clipping does the same operations as before the waves' shortcuts
  const WaterProperties water{kRho, kG, 0.4, 30.0, 5.0, 100.0};
  const AiryWaves calm(water), later(water, {{1.0, 5.0, 0.7, 0.3}});
  const TriangleMesh hull = boxMesh(Vector3(20.0, 8.0, 4.0), 6, 3, 2);
  for (const AiryWaves* sea : {&calm, &later}) {
    SubmergedWorkspace ws(hull, sea->size());
    Transform X = Transform::translation(Vector3(3.0, -2.0, 0.9));
    X.R = (Eigen::AngleAxisd(0.3, Vector3::UnitZ()) * Eigen::AngleAxisd(0.2, Vector3::UnitX()))
              .toRotationMatrix();
    const SubmergedProperties got = integrateSubmerged(hull, X, *sea, 50.0, ws, true);
    const auto [F, M] = midpointRule(ws, got.wetTriangles, [&](const Vector3& q) {
      return q.z() < water.level ? kRho * kG * (water.level - q.z()) : 0.0;
    });
    CHECK(got.wetTriangles > 20);
    CHECK(got.force == F);
    CHECK(got.moment == M);
  }
}
