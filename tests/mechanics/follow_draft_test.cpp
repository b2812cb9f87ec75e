// The added mass following the draft in a running scene (mechanics/follow_draft.hpp with
// forces/hydro/draft_added_mass.hpp): a 20 x 8 x 4 m box hung on a wire and lowered slowly into
// still water carries on the wire its weight less its buoyancy, and while the winch stops, the
// inertia of its mass plus A33 (panel solver, at its draft then); released, it heaves free at
// 2 pi sqrt((M + A33) / (rho g A_wp)) with A33 from the panel solver at its floating draft, and
// the energy balance closes with the added mass growing. A box held at a tabulated draft (a
// surge oscillation on two ropes) gives exactly the results of the constant added mass.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <vector>

#include "dynamics/added_mass.hpp"
#include "forces/geometry/mesh_io.hpp"
#include "forces/geometry/primitive_meshes.hpp"
#include "forces/hydro/added_mass.hpp"
#include "run/runner.hpp"
#include "scene/assembler.hpp"
#include "scene/scene_loader.hpp"
#include "support/csv_file.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;
using dynamics::Matrix6;
using dynamics::Vector3;

namespace {

constexpr double kRho = 1025.0, kG = 9.81, kMass = 4.0e5, kL = 20.0, kB = 8.0;

// (scene text in a directory holding box.obj, end time) => its time series
testing::CsvFile runBox(testing::SceneDir& dir, const std::string& yaml, double until,
                        const std::string& out = "out") {
  forces::writeObj(forces::boxMesh(Vector3(kL, kB, 4), 10, 4, 4), dir.file("box.obj"));
  auto scene = scene::loadSceneOrThrow(dir.write("s.yaml", yaml));
  auto root = scene::assemble(*scene);
  run::runScene(*scene, *root, {dir.path() / out, until, {}, {}});
  return testing::CsvFile((dir.path() / out / "timeseries.csv").string());
}

// (hull at draft d, origin mid-depth) => A33 by the panel solver, kg
double heaveAddedMass(double draft) {
  const Matrix6 A = forces::hydro::floatingAddedMass(
      forces::hydro::panelMesh(forces::boxMesh(Vector3(kL, kB, 4), 10, 4, 4)),
      dynamics::Transform::translation(Vector3(0, 0, 2.0 - draft)), kRho, 0.0);
  return A(2, 2);
}

// the box hung on a wire from (0, 0, 30), its keel 0.5 m above the still water; lowered 2.5 m
// at 0.05 m/s from 1 s (to 56 s), then paid out 3 m at 0.1 m/s (to 96 s): it floats free; the
// winch ramps at 0.01 m/s^2, the wire is damped (its 0.44 s bounce on the box)
const char* kLowered = R"(schema_version: 1
integrator: {method: rk4, dt: 0.01}
components:
  lower: {type: wire_actor, params: {rope: wire, payout: 2.5, speed: 0.05, accel: 0.01, start_at: 1}}
  release: {type: wire_actor, params: {rope: wire, payout: 3.0, speed: 0.1, accel: 0.01, after_all: [lower]}}
mechanics:
  gravity: [0, 0, -9.81]
  equilibrium: true
  water: {density: 1025.0, level: 0.0}
  bodies:
    box:
      parent: world
      joint: {type: free, q0: {xyz: [0, 0, 2.5]}}
      mass: 4.0e5
      inertia: [2.7e6, 1.4e7, 1.5e7]
      added_mass: {hull: box.obj, follow_draft: [0.25, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0]}
  hydrostatics:
    box_hull: {body: box, mesh: box.obj}
  ropes:
    wire: {path: [{body: world, point: [0, 0, 30]}, {body: box, point: [0, 0, 2]}], EA: 2.0e9, L0: 25.45,
           damping: 2.0e6}
record: {interval: 0.05}
)";

// (time series, time s) => the first row at or after s (the last one when none is)
std::vector<double> rowAt(const testing::CsvFile& csv, double s) {
  for (const auto& r : csv.rows)
    if (r[0] >= s - 1e-9) return r;
  return csv.rows.back();
}

}  // namespace

TEST_CASE("a box lowered slowly into still water hangs on its weight less its buoyancy") {
  testing::SceneDir dir;
  const auto csv = runBox(dir, kLowered, 56.0);
  const int t = 0, tension = csv.column("wire.tension[N]"),
            disp = csv.column("box_hull.displacement[kg]"), z = csv.column("box.z[m]");
  REQUIRE(std::min({tension, disp, z}) > 0);
  const double W = kMass * kG;
  // (A33 of the panel solver at the scene's drafts) => its slope at a draft (the table's)
  const std::vector<double> drafts{0.0, 0.25, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0};
  std::vector<double> a33{0.0};
  for (std::size_t k = 1; k < drafts.size(); ++k) a33.push_back(heaveAddedMass(drafts[k]));
  auto slope = [&](double d) {
    for (std::size_t k = 1; k < drafts.size(); ++k)
      if (d < drafts[k]) return (a33[k] - a33[k - 1]) / (drafts[k] - drafts[k - 1]);
    return 0.0;
  };
  // (lowered at a steady 0.05 m/s: 6 .. 51 s) => the wire carries W - rho g V less the entry
  // force A33' w^2 (the growing added mass taking momentum from the box), to 0.2 % of W: the
  // entry force steps where the table's slope does, and the wire bounces (0.44 s) a little there
  int wet = 0;
  double entry = 0, entered = 0, m = 0;
  for (const auto& r : csv.rows) {
    if (r[t] < 6.0 || r[t] > 51.0 || r[disp] < 0.02 * kMass) continue;
    ++wet;
    const double d = 2.0 - r[z], F = slope(d) * 0.05 * 0.05, lack = W - r[disp] * kG - r[tension];
    INFO("t = " << r[t] << " s, buoyancy " << r[disp] * kG << " N, entry force " << F
                << " N, tension " << r[tension] << " N");
    CHECK(std::abs(lack - F) < 2e-3 * W);
    if (d > 0.1 && d < 0.2) {  // (the entry: the first 0.25 m) => its mean lack against A33' w^2
      entry += F;
      entered += lack;
      m += 1;
    }
  }
  CHECK(wet >= 200);
  REQUIRE(m > 10);
  INFO("entry force " << entry / m << " N, the wire's mean lack then " << entered / m << " N");
  CHECK(entry / m > 1e-3 * W);
  CHECK(entered / m == Approx(entry / m).epsilon(0.1));
  CHECK(csv.rows.back()[disp] > 0.7 * kMass);  // most of the weight has moved to the water
  // (the winch stopping at 0.01 m/s^2: 51 .. 56 s) => the wire also decelerates the box and the
  // water it carries: (M + A33) a more, A33 the panel solver's at the box's draft then
  double sum = 0, n = 0, draft = 0;
  for (const auto& r : csv.rows) {
    if (r[t] < 52.0 || r[t] > 55.5) continue;
    sum += r[tension] - (W - r[disp] * kG);
    draft += 2.0 - r[z];
    n += 1;
  }
  REQUIRE(n > 10);
  const double A33 = heaveAddedMass(draft / n);
  INFO("draft " << draft / n << " m, A33 " << A33 << " kg, extra pull " << sum / n << " N");
  CHECK(sum / n == Approx((kMass + A33) * 0.01).epsilon(0.1));
}

TEST_CASE("released it heaves at the period of its mass plus the added mass at its draft") {
  testing::SceneDir dir;
  const auto csv = runBox(dir, kLowered, 140.0);
  const int t = 0, z = csv.column("box.z[m]"), tension = csv.column("wire.tension[N]"),
            balance = csv.column("mechanics.energy_balance[J]");
  REQUIRE(std::min({z, tension, balance}) > 0);
  // (after the wire has gone slack: from 100 s) => upward crossings of the mean heave
  const double T = kMass / (kRho * kL * kB), zf = 2.0 - T;
  std::vector<double> up;
  double lo = 1e9, hi = -1e9;
  for (std::size_t k = 1; k < csv.rows.size(); ++k) {
    const auto &a = csv.rows[k - 1], &b = csv.rows[k];
    if (a[t] < 100.0) continue;
    CHECK(b[tension] == 0.0);
    lo = std::min(lo, b[z]);
    hi = std::max(hi, b[z]);
    if (a[z] < zf && b[z] >= zf) up.push_back(a[t] + (b[t] - a[t]) * (zf - a[z]) / (b[z] - a[z]));
  }
  INFO("heave between " << lo << " and " << hi << " m about " << zf << " m");
  REQUIRE(up.size() >= 4);
  REQUIRE(hi - lo > 0.01);
  const double period = (up.back() - up.front()) / static_cast<double>(up.size() - 1);
  const double A33 = heaveAddedMass(T), C33 = kRho * kG * kL * kB;
  INFO("A33 at the floating draft " << T << " m: " << A33 << " kg (" << A33 / kMass << " M)");
  CHECK(period == Approx(2 * M_PI * std::sqrt((kMass + A33) / C33)).epsilon(0.002));
  CHECK(period > 1.2 * 2 * M_PI * std::sqrt(kMass / C33));  // without the added mass: far shorter
  // (energy balance, kinetic energy with the added mass at each draft) => closed to a small
  // fraction of the work the winch has done
  double drift = 0;
  for (const auto& r : csv.rows)
    drift = std::max(drift, std::abs(r[balance] - csv.rows[0][balance]));
  const double scale = kMass * kG * 2.5;
  INFO("energy balance drift " << drift << " J against " << scale << " J");
  CHECK(drift < 1e-4 * scale);
}

TEST_CASE("a box at a tabulated draft gives exactly the results of its constant added mass") {
  // (surge on a prismatic joint between two taut ropes at draft 2 m, started at 0.05 m/s) => the
  // same time series with `follow_draft` as with the constant matrix at the initial position
  auto scene = [](const std::string& addedMass) {
    return std::string(R"(schema_version: 1
integrator: {method: rk4, dt: 0.01}
mechanics:
  gravity: [0, 0, -9.81]
  water: {density: 1025.0, level: 0.0}
  bodies:
    box:
      parent: world
      joint: {type: prismatic, axis: [1, 0, 0], q0: 0, v0: 0.05}
      mass: 4.0e5
      inertia: [2.7e6, 1.4e7, 1.5e7]
      added_mass: )") +
           addedMass + R"(
  ropes:
    east: {path: [{body: world, point: [30, 0, 0]}, {body: box, point: [10, 0, 0]}], EA: 1.0e6, L0: 19.9}
    west: {path: [{body: world, point: [-30, 0, 0]}, {body: box, point: [-10, 0, 0]}], EA: 1.0e6, L0: 19.9}
record: {interval: 0.1}
)";
  };
  testing::SceneDir dir;
  const auto constant = runBox(dir, scene("{hull: box.obj}"), 30.0, "constant");
  const auto follows =
      runBox(dir, scene("{hull: box.obj, follow_draft: [1.0, 2.0, 3.0]}"), 30.0, "follows");
  // (the files without their header comments, which name the scene and its hash) => equal bytes
  auto body = [&](const char* run) {
    std::ifstream in(dir.path() / run / "timeseries.csv");
    std::string line, out;
    while (std::getline(in, line))
      if (line.empty() || line[0] != '#') out += line + "\n";
    return out;
  };
  REQUIRE(constant.rows.size() > 250);
  CHECK(body("constant") == body("follows"));
  // and the surge period is that of the mass plus A11 on the two ropes (k = 2 EA / L0)
  const int t = 0, x = follows.column("box.x[m]");
  REQUIRE(x > 0);
  std::vector<double> up;
  for (std::size_t k = 1; k < follows.rows.size(); ++k) {
    const auto &p = follows.rows[k - 1], &r = follows.rows[k];
    if (p[x] < 0 && r[x] >= 0) up.push_back(p[t] + (r[t] - p[t]) * -p[x] / (r[x] - p[x]));
  }
  REQUIRE(up.size() >= 2);
  const Matrix6 A = forces::hydro::floatingAddedMass(
      forces::hydro::panelMesh(forces::boxMesh(Vector3(kL, kB, 4), 10, 4, 4)),
      dynamics::Transform::identity(), kRho, 0.0);
  const double k = 2 * 1.0e6 / 19.9;
  CHECK((up.back() - up.front()) / static_cast<double>(up.size() - 1) ==
        Approx(2 * M_PI * std::sqrt((kMass + A(0, 0)) / k)).epsilon(0.005));
}

TEST_CASE("a trolley started at once on a floating box makes it recoil with its added mass") {
  // (the box lowered from the air to a 2 m draft by a servo on its heave joint, 1 .. 4.5 s, then a
  // 200 t trolley on its deck started by a prescribed joint_actor at 6 s: a velocity step of
  // 0.5 m/s) => the surge momentum of the box, the water it carries and the trolley stays zero,
  // (M + A11) V + m (V + 0.5) = 0: the box recoils at V = -0.5 m / (M + A11 + m), A11 the panel
  // solver's at the 2 m draft; and the impulse's work is the kinetic energy it gave the box, the
  // trolley and the water (the energy balance does not jump). With the added mass of the box's
  // start (dry: none) in the impulse, the recoil is 4 % faster and the balance jumps by
  // A11 V^2 / 2.
  const char* yaml = R"(schema_version: 1
integrator: {method: rk4, dt: 0.01}
components:
  lower: {type: joint_actor, params: {joint: heave, target: 0.0, speed: 1.0, start_at: 1.0}}
  start: {type: joint_actor, params: {joint: trolley_x, target: 2.0, speed: 0.5, mode: prescribed, start_at: 6.0}}
mechanics:
  gravity: [0, 0, 0]
  drive_bandwidth: 5.0
  water: {density: 1025.0, level: 0.0}
  bodies:
    carrier:
      parent: world
      joint: {name: heave, type: prismatic, axis: [0, 0, 1], q0: 2.5, hold: true}
      mass: 1.0e3
      inertia: [1.0e3, 1.0e3, 1.0e3]
    box:
      parent: carrier
      joint: {type: prismatic, axis: [1, 0, 0], q0: 0}
      mass: 4.0e5
      inertia: [2.7e6, 1.4e7, 1.5e7]
      added_mass: {hull: box.obj, follow_draft: [1.0, 2.0, 3.0]}
    trolley:
      parent: box
      joint: {name: trolley_x, type: prismatic, axis: [1, 0, 0], q0: 0}
      placement: {xyz: [0, 0, 3]}
      mass: 2.0e5
      inertia: [1.0e5, 1.0e5, 1.0e5]
record: {interval: 0.05}
)";
  testing::SceneDir dir;
  const auto csv = runBox(dir, yaml, 11.0);
  const int t = 0, x = csv.column("box.x[m]"), z = csv.column("box.z[m]"),
            balance = csv.column("mechanics.energy_balance[J]");
  REQUIRE(std::min({x, z, balance}) > 0);
  auto at = [&](double s) { return rowAt(csv, s); };
  // (box.x over the ramp, 6.5 .. 9.5 s: the trolley moves 2 m at 0.5 m/s from 6 s) => V
  const auto r0 = at(6.5), r1 = at(9.5);
  REQUIRE(std::abs(r0[z]) < 1e-3);  // lowered to its 2 m draft and held there
  const Matrix6 A = forces::hydro::floatingAddedMass(
      forces::hydro::panelMesh(forces::boxMesh(Vector3(kL, kB, 4), 10, 4, 4)),
      dynamics::Transform::identity(), kRho, 0.0);
  const double m = 2.0e5, V = (r1[x] - r0[x]) / (r1[t] - r0[t]);
  INFO("A11 " << A(0, 0) << " kg, recoil " << V << " m/s");
  REQUIRE(A(0, 0) > 0.05 * kMass);
  CHECK(V == Approx(-0.5 * m / (kMass + A(0, 0) + m)).epsilon(0.002));
  // (the trolley locked at 2 m: 10 s) => the box stops with it (against 0.08 m while moving)
  CHECK(std::abs(csv.rows.back()[x] - at(10.5)[x]) < 1e-5);
  // (each impulse) => no jump in the energy balance, against the kinetic energy it gives
  const double kinetic = 0.5 * ((kMass + A(0, 0)) * V * V + m * (V + 0.5) * (V + 0.5));
  for (const double s : {6.0, 10.0}) {
    const double jump = at(s + 0.1)[balance] - at(s - 0.1)[balance];
    INFO("t = " << s << " s: the balance moves " << jump << " J; kinetic energy " << kinetic
                << " J");
    CHECK(std::abs(jump) < 1e-6 * kinetic);
  }
}

TEST_CASE(
    "a floating box welded in a closed loop accelerates with its added mass under generalized "
    "alpha") {
  // (the box lowered from the air to a 2 m draft by a servo on its heave joint, 1 .. 4.5 s; a 200 t
  // rider on a free joint welded to its deck by a loop closure; pushed along x by 10 kN from 6 s,
  // generalized alpha: its loop terms take the mass matrix with the added mass at the stage's
  // draft) => x = F t^2 / (2 (M + A11 + m)), A11 the panel solver's at the 2 m draft (with no
  // added mass in the loop terms' mass matrix, as at the box's dry start, it came out 2.5 % low)
  const char* yaml = R"(schema_version: 1
integrator: {method: generalized_alpha, dt: 0.01}
components:
  lower: {type: joint_actor, params: {joint: heave, target: 0.0, speed: 1.0, start_at: 1.0}}
mechanics:
  gravity: [0, 0, 0]
  drive_bandwidth: 5.0
  water: {density: 1025.0, level: 0.0}
  bodies:
    carrier:
      parent: world
      joint: {name: heave, type: prismatic, axis: [0, 0, 1], q0: 2.5, hold: true}
      mass: 1.0e3
      inertia: [1.0e3, 1.0e3, 1.0e3]
    box:
      parent: carrier
      joint: {type: prismatic, axis: [1, 0, 0], q0: 0}
      mass: 4.0e5
      inertia: [2.7e6, 1.4e7, 1.5e7]
      added_mass: {hull: box.obj, follow_draft: [1.0, 2.0, 3.0]}
    rider:
      parent: world
      joint: {type: free, q0: {xyz: [0, 0, 5.5]}}
      mass: 2.0e5
      inertia: [1.0e5, 1.0e5, 1.0e5]
  loops:
    weld: {body_a: box, frame_a: {xyz: [0, 0, 3]}, body_b: rider, frame_b: {xyz: [0, 0, 0]}, constrain: weld}
  loads:
    push: {body: box, frame: world, series: [[0, 0, 0, 0, 0, 0, 0], [6, 0, 0, 0, 0, 0, 0], [6.0001, 1.0e4, 0, 0, 0, 0, 0], [11, 1.0e4, 0, 0, 0, 0, 0]]}
record: {interval: 0.05}
)";
  testing::SceneDir dir;
  const auto csv = runBox(dir, yaml, 11.0);
  const int x = csv.column("box.x[m]"), z = csv.column("box.z[m]");
  REQUIRE(std::min(x, z) > 0);
  auto at = [&](double s) { return rowAt(csv, s); };
  REQUIRE(std::abs(at(6.0)[z]) < 0.01);  // lowered to its 2 m draft
  const Matrix6 A = forces::hydro::floatingAddedMass(
      forces::hydro::panelMesh(forces::boxMesh(Vector3(kL, kB, 4), 10, 4, 4)),
      dynamics::Transform::identity(), kRho, 0.0);
  // (x at 8 and 11 s, from where it was at 6 s) => the acceleration, twice
  const double x6 = at(6.0)[x], a8 = 2 * (at(8.0)[x] - x6) / 4.0,
               a11 = 2 * (at(11.0)[x] - x6) / 25.0;
  const double expected = 1.0e4 / (kMass + A(0, 0) + 2.0e5);
  INFO("A11 " << A(0, 0) << " kg; acceleration " << a8 << ", " << a11 << " m/s^2, expected "
              << expected);
  CHECK(a8 == Approx(expected).epsilon(0.005));
  CHECK(a11 == Approx(expected).epsilon(0.005));
}
