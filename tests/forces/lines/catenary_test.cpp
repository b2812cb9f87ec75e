// The quasi-static elastic catenary against independent references: the regression values
// MoorPy asserts (NREL/MoorPy tests/test_catenary.py: suspended, touching down with and without
// sea-bed friction, hanging below the anchor, buoyant), the inextensible catenary's classic
// closed forms (EA -> infinity), a line lying on the sea bed (hand formulas), the slack line
// hanging under its fairlead; the analytic Jacobian against finite differences; the profile's
// ends and touchdown; the stored energy against a quadrature of the profile and, without
// friction, its gradient equal to the fairlead tension; warm starts.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

#include "forces/lines/catenary.hpp"

using namespace yardsim::forces;

namespace {

// (f decreasing in c on [lo, hi] with a root) => the root by bisection in log c
double bisect(const std::function<double(double)>& f, double lo, double hi) {
  for (int i = 0; i < 200; ++i) {
    const double mid = std::sqrt(lo * hi);
    (f(mid) > 0.0 ? lo : hi) = mid;
  }
  return std::sqrt(lo * hi);
}

// (p, XF, ZF) => the solution, required converged
CatenarySolution solved(const CatenaryParameters& p, double xf, double zf) {
  const CatenarySolution s = solveCatenary(p, xf, zf);
  REQUIRE(s.status == CatenaryStatus::Converged);
  return s;
}

// (p, XF, ZF) => max over the four entries of |analytic - central difference| / max |entry|
double jacobianError(const CatenaryParameters& p, double xf, double zf) {
  const CatenarySolution s = solved(p, xf, zf);
  const double d = 1e-5 * p.length;
  const CatenarySolution xp = solved(p, xf + d, zf), xm = solved(p, xf - d, zf);
  const CatenarySolution zp = solved(p, xf, zf + d), zm = solved(p, xf, zf - d);
  const double fd[4] = {(xp.hf - xm.hf) / (2 * d), (zp.hf - zm.hf) / (2 * d),
                        (xp.vf - xm.vf) / (2 * d), (zp.vf - zm.vf) / (2 * d)};
  const double an[4] = {s.k11, s.k12, s.k21, s.k22};
  double scale = 0.0, err = 0.0;
  for (int i = 0; i < 4; ++i) {
    scale = std::max(scale, std::abs(an[i]));
    err = std::max(err, std::abs(an[i] - fd[i]));
  }
  return err / scale;
}

// (p, solution, XF) => integral over the line of w z + T^2 / (2 EA) by composite Simpson, split
// at the touchdown point
double energyByQuadrature(const CatenaryParameters& p, const CatenarySolution& s, double xf) {
  auto g = [&](double u) {
    const CatenaryPoint pt = catenaryPoint(p, s, xf, u);
    return p.weight * pt.z + (std::isinf(p.ea) ? 0.0 : pt.tension * pt.tension / (2.0 * p.ea));
  };
  auto simpson = [&](double a, double b) {
    const int n = 20000;
    const double h = (b - a) / n;
    double sum = g(a) + g(b);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * g(a + i * h);
    return sum * h / 3.0;
  };
  return simpson(0.0, s.laidLength) + simpson(s.laidLength, p.length);
}

}  // namespace

TEST_CASE("MoorPy's catenary regression cases") {
  // NREL/MoorPy tests/test_catenary.py: inputs (XF, ZF, L, EA, w, CB) and its asserted
  // (fAH, fAV, fBH, fBV, LBot); MoorPy's CB < 0 means no sea-bed contact, its fB is the force
  // on B (= -HF, -VF here) and fA the force on A (= HA, VA). Its values satisfy Irvine's
  // equations to 4e-6 .. 4e-5 m in span (MoorPy's convergence tolerance), ours to 1e-9 m, so
  // the agreement is bounded near 1e-6 relative, not the 1e-7 MoorPy asserts of itself.
  struct Case {
    double xf, zf, L, ea, w, cb;
    double fAH, fAV, fBH, fBV, lBot;
  };
  const Case cases[] = {
      // touching down, friction 5: the anchor holds nothing
      {400, 200, 500.0, 7.51e12, 800.0, 5.0, 0.0, 0.0, -96643.43501616362, -237751.75997440016,
       202.81030003199982},
      // touching down, no friction
      {400, 200, 500.0, 7.51e12, 800.0, 0.0, 96643.42815934008, 0.0, -96643.42815934008,
       -237751.75535996316, 202.81030580004602},
      // touching down, friction 0.1: the anchor holds HF - CB w LBot
      {400, 200, 500.0, 7.51e12, 800.0, 0.1, 80418.60434855078, 0.0, -96643.42877136687,
       -237751.75577183915, 202.81030528520108},
      // suspended, hanging below the anchor (VA < 0), no sea bed
      {400, 200, 500.0, 7.51e12, 200.0, -372.7, 43694.580989249596, -22365.599350216216,
       -43694.580989249596, -77634.40064978378, 0},
      // suspended, elastic (EA = 7.51e8 N), hanging below the anchor
      {89.9, 59.2, 130.0, 7.51e8, 881.05, -372.7, 31373.229006023103, -26650.341270116318,
       -31373.229006023103, -87886.15872988368, 0},
      // buoyant (w < 0), elastic
      {37.96888656874307, 20.49078283711694, 100.0, 7.51e8, -881.0549577007893, -1245.2679469540894,
       6428.437434537766, 53178.729367882406, -6428.437434537766, 34926.76640219652, 0}};
  double worst = 0.0;
  for (const Case& c : cases) {
    const CatenaryParameters p{c.L, c.ea, c.w, c.cb >= 0.0, std::max(c.cb, 0.0)};
    const CatenarySolution s = solved(p, c.xf, c.zf);
    const double got[5] = {s.ha, s.va, -s.hf, -s.vf, s.laidLength};
    const double want[5] = {c.fAH, c.fAV, c.fBH, c.fBV, c.lBot};
    for (int i = 0; i < 5; ++i) {
      if (want[i] == 0.0) {
        CHECK(got[i] == 0.0);  // an exact zero in MoorPy is one here too
        continue;
      }
      const double rel = std::abs(got[i] - want[i]) / std::abs(want[i]);
      worst = std::max(worst, rel);
      CHECK(rel < 1e-6);
    }
    CHECK(s.iterations <= 10);  // from a cold start
    // (our solution) => it satisfies the spans to 1e-9 m: the profile ends at B
    const CatenaryPoint b = catenaryPoint(p, s, c.xf, c.L);
    CHECK(std::abs(b.x - c.xf) < 1e-9);
    CHECK(std::abs(b.z - c.zf) < 1e-9);
  }
  WARN("worst relative difference from MoorPy: " << worst);
}

TEST_CASE("EA -> infinity: the inextensible catenary's closed forms") {
  const double a = 400.0, h = 200.0, L = 500.0, w = 800.0;
  const double inf = std::numeric_limits<double>::infinity();
  SECTION("suspended: sqrt(L^2 - h^2) = 2 c sinh(a / 2c), V_B = w c sinh(atanh(h/L) + a/2c)") {
    const double c = bisect(
        [&](double cc) { return 2 * cc * std::sinh(a / (2 * cc)) - std::sqrt(L * L - h * h); },
        a / 1400.0, 1e6);
    const double vB = w * c * std::sinh(std::atanh(h / L) + a / (2 * c));
    const CatenarySolution s = solved({L, inf, w, false, 0.0}, a, h);
    CHECK(s.hf == Approx(w * c).epsilon(1e-11));
    CHECK(s.vf == Approx(vB).epsilon(1e-11));
    // and a stiff elastic line tends to it as 1/EA
    const CatenarySolution e6 = solved({L, 1e10, w, false, 0.0}, a, h);
    const CatenarySolution e7 = solved({L, 1e11, w, false, 0.0}, a, h);
    CHECK(std::abs(e7.hf - w * c) < 0.11 * std::abs(e6.hf - w * c));
  }
  SECTION(
      "touching down: L - sqrt(h^2 + 2 h c) + c acosh(1 + h/c) = a, V_B = w sqrt(h^2 + 2 h c)") {
    const double c = bisect(
        [&](double cc) {
          return -(L - std::sqrt(h * h + 2 * h * cc) + cc * std::acosh(1 + h / cc) - a);
        },
        1e-3, 1e6);
    const CatenarySolution s = solved({L, inf, w, true, 0.0}, a, h);
    CHECK(s.profile == CatenaryProfile::TouchingDown);
    CHECK(s.hf == Approx(w * c).epsilon(1e-11));
    CHECK(s.vf == Approx(w * std::sqrt(h * h + 2 * h * c)).epsilon(1e-11));
    CHECK(s.laidLength == Approx(L - std::sqrt(h * h + 2 * h * c)).epsilon(1e-11));
    CHECK(s.touchdownX == Approx(s.laidLength).epsilon(1e-12));  // no stretch on the bed
  }
}

TEST_CASE("a line lying on the sea bed: the stretch with and without friction by hand") {
  const double L = 100.0, ea = 1e6, w = 100.0;
  // no friction: H = EA (XF/L - 1)
  CatenarySolution s = solved({L, ea, w, true, 0.0}, 100.3, 0.0);
  CHECK(s.profile == CatenaryProfile::OnSeabed);
  CHECK(s.hf == Approx(3000.0).epsilon(1e-12));
  CHECK(s.ha == Approx(3000.0).epsilon(1e-12));
  // CB = 0.5 (CB w L = 5000 N): a small stretch leaves the anchor slack, H^2/(2 CB w EA) = XF - L
  s = solved({L, ea, w, true, 0.5}, 100.1, 0.0);
  CHECK(s.hf == Approx(std::sqrt(2.0 * 0.5 * w * ea * 0.1)).epsilon(1e-12));
  CHECK(s.ha == 0.0);
  // a large one loads it: H L/EA - CB w L^2/(2 EA) = XF - L, HA = H - CB w L
  s = solved({L, ea, w, true, 0.5}, 101.0, 0.0);
  CHECK(s.hf == Approx(12500.0).epsilon(1e-12));
  CHECK(s.ha == Approx(7500.0).epsilon(1e-12));
  // the touching-down solution tends to these as B rises off the bed by a micrometre
  const CatenarySolution up = solved({L, ea, w, true, 0.5}, 101.0, 1e-6);
  CHECK(up.profile == CatenaryProfile::TouchingDown);
  CHECK(up.hf == Approx(12500.0).epsilon(1e-4));
  CHECK(up.ha == Approx(7500.0).epsilon(1e-4));
  // shorter than L: slack, no tension
  s = solved({L, ea, w, true, 0.5}, 90.0, 0.0);
  CHECK(s.hf == 0.0);
  CHECK(s.vf == 0.0);
  CHECK(solveCatenary({L, ea, w, true, 0.5}, 90.0, -1.0).status == CatenaryStatus::BelowSeabed);
}

TEST_CASE("a slack line hangs under its fairlead: HF = 0, VF = w LH, LH + w LH^2/(2 EA) = ZF") {
  const CatenaryParameters p{300.0, 5e6, 500.0, true, 1.0};
  const CatenarySolution s = solved(p, 150.0, 80.0);
  CHECK(s.profile == CatenaryProfile::Slack);
  CHECK(s.hf == 0.0);
  const double lh = s.vf / p.weight;
  CHECK(lh + p.weight * lh * lh / (2 * p.ea) == Approx(80.0).epsilon(1e-13));
  CHECK(s.laidLength == Approx(300.0 - lh).epsilon(1e-13));
  // d VF / d ZF against a finite difference
  const double d = 1e-4;
  CHECK(s.k22 == Approx((solved(p, 150.0, 80.0 + d).vf - solved(p, 150.0, 80.0 - d).vf) / (2 * d))
                     .epsilon(1e-8));
  // just taut enough to lift: the touching-down solution continues it with a small HF
  const CatenarySolution t = solved(p, 300.0 - lh + 0.5, 80.0);
  CHECK(t.profile == CatenaryProfile::TouchingDown);
  CHECK(t.hf > 0.0);
  CHECK(t.hf < 0.05 * t.vf);
}

TEST_CASE("the analytic 2x2 Jacobian agrees with finite differences on every profile") {
  CHECK(jacobianError({500.0, 7.51e8, 800.0, false, 0.0}, 400.0, 200.0) < 1e-6);    // suspended
  CHECK(jacobianError({500.0, 7.51e8, 200.0, false, 0.0}, 400.0, 200.0) < 1e-6);    // U-shaped
  CHECK(jacobianError({500.0, 7.51e8, 800.0, true, 0.0}, 400.0, 200.0) < 1e-6);     // touchdown
  CHECK(jacobianError({500.0, 1e7, 800.0, true, 0.3}, 400.0, 200.0) < 1e-6);        // friction,
  CHECK(jacobianError({500.0, 1e7, 800.0, true, 5.0}, 400.0, 200.0) < 1e-6);        // both regimes
  CHECK(jacobianError({100.0, 7.51e8, -881.05, false, 0.0}, 37.97, 20.49) < 1e-6);  // buoyant
  CHECK(jacobianError({130.0, 7.51e8, 881.05, false, 0.0}, 89.9, -59.2) < 1e-6);    // B below A
}

TEST_CASE("the profile: its ends, tensions, touchdown, and the stored energy") {
  struct Line {
    CatenaryParameters p;
    double xf, zf;
  };
  const Line lines[] = {{{500.0, 1e8, 800.0, false, 0.0}, 400.0, 200.0},
                        {{500.0, 1e7, 800.0, true, 0.0}, 400.0, 200.0},
                        {{500.0, 1e7, 800.0, true, 0.3}, 400.0, 200.0},
                        {{100.0, 7.51e8, -881.05, false, 0.0}, 37.97, 20.49},
                        {{300.0, 5e6, 500.0, true, 0.0}, 150.0, 80.0}};
  for (const Line& l : lines) {
    const CatenarySolution s = solved(l.p, l.xf, l.zf);
    const CatenaryPoint a = catenaryPoint(l.p, s, l.xf, 0.0),
                        b = catenaryPoint(l.p, s, l.xf, l.p.length);
    CHECK(std::abs(a.x) + std::abs(a.z) < 1e-12);
    CHECK(std::abs(b.x - l.xf) < 1e-8);
    CHECK(std::abs(b.z - l.zf) < 1e-8);
    CHECK(b.tension == Approx(std::hypot(s.hf, s.vf)).epsilon(1e-12));
    CHECK(a.tension == Approx(std::hypot(s.ha, s.va)).margin(1e-9 * b.tension));
    if (s.profile == CatenaryProfile::TouchingDown) {
      CHECK(catenaryPoint(l.p, s, l.xf, 0.5 * s.laidLength).z == 0.0);
      CHECK(catenaryPoint(l.p, s, l.xf, s.laidLength).x == Approx(s.touchdownX).epsilon(1e-14));
      CHECK(catenaryPoint(l.p, s, l.xf, s.laidLength + 1.0).z > 0.0);
    }
    const double v = catenaryEnergy(l.p, s);
    CHECK(v == Approx(energyByQuadrature(l.p, s, l.xf)).epsilon(1e-9));
    // without friction the line is conservative: dV/dXF = HF, dV/dZF = VF
    if (l.p.friction == 0.0) {
      const double d = 1e-4;
      const double dvx = (catenaryEnergy(l.p, solved(l.p, l.xf + d, l.zf)) -
                          catenaryEnergy(l.p, solved(l.p, l.xf - d, l.zf))) /
                         (2 * d);
      const double dvz = (catenaryEnergy(l.p, solved(l.p, l.xf, l.zf + d)) -
                          catenaryEnergy(l.p, solved(l.p, l.xf, l.zf - d))) /
                         (2 * d);
      CHECK(dvx == Approx(s.hf).margin(1e-6 * b.tension));
      CHECK(dvz == Approx(s.vf).margin(1e-6 * b.tension));
    }
  }
}

TEST_CASE("a warm start converges in a few iterations to the cold start's solution") {
  const CatenaryParameters p{500.0, 7.51e8, 800.0, true, 0.2};
  CatenarySolution s = solved(p, 400.0, 200.0);
  for (int k = 1; k <= 20; ++k) {  // a fairlead moving 2 cm and 1 cm per call
    const double xf = 400.0 + 0.02 * k, zf = 200.0 - 0.01 * k;
    const CatenarySolution warm = solveCatenary(p, xf, zf, s.hf, s.vf);
    const CatenarySolution cold = solved(p, xf, zf);
    CHECK(warm.status == CatenaryStatus::Converged);
    CHECK(warm.iterations <= 3);
    CHECK(warm.hf == Approx(cold.hf).epsilon(1e-10));
    CHECK(warm.vf == Approx(cold.vf).epsilon(1e-10));
    s = warm;
  }
  CHECK(solveCatenary({0.0, 1e8, 800.0, false, 0.0}, 1.0, 1.0).status == CatenaryStatus::BadInput);
  CHECK(solveCatenary({10.0, 1e8, 0.0, false, 0.0}, 1.0, 1.0).status == CatenaryStatus::BadInput);
  CHECK(std::string(catenaryParameterError({10.0, -1.0, 1.0, false, 0.0})).size() > 0);
}

TEST_CASE("cold starts converge over the whole range of spans, every profile, B above or below A") {
  // sinking, on the bed, with friction, buoyant, nearly inextensible; XF from 1e-9 L to 1.01 L,
  // ZF from -0.5 L to 1.01 L (not below the bed)
  int solves = 0, failed = 0, worstIterations = 0;
  double worstMiss = 0.0;
  for (int kind = 0; kind < 5; ++kind) {
    const CatenaryParameters p{500.0, kind == 4 ? 1e12 : 7.5e8, kind == 3 ? -800.0 : 1020.0,
                               kind == 1 || kind == 2, kind == 2 ? 1.0 : 0.0};
    for (int i = 0; i <= 60; ++i) {
      for (int j = -30; j <= 60; ++j) {
        const double xf = 5e-7 + 505.0 * i / 60.0, zf = 505.0 * j / 60.0;
        if (p.seabed && zf < 0.0) continue;
        const CatenarySolution s = solveCatenary(p, xf, zf);
        ++solves;
        if (s.status != CatenaryStatus::Converged) {
          ++failed;
          continue;
        }
        worstIterations = std::max(worstIterations, s.iterations);
        const CatenaryPoint b = catenaryPoint(p, s, xf, p.length);
        worstMiss = std::max(worstMiss, std::abs(b.x - xf) + std::abs(b.z - zf));
      }
    }
  }
  CHECK(solves > 20000);
  CHECK(failed == 0);
  CHECK(worstMiss < 1e-7);  // m, on a 500 m line
  CHECK(worstIterations <= 40);
}
