#include "forces/lines/catenary.hpp"

#include <algorithm>
#include <cmath>

namespace yardsim::forces {

namespace {

// The spans of one profile and their derivatives with respect to (HF, VF).
struct Spans {
  double x = 0.0, z = 0.0;
  double xh = 0.0, xv = 0.0, zh = 0.0, zv = 0.0;
};

// (p, 1/EA, H > 0, V) => spans of a fully suspended line (Irvine's equations, any sign of w and
// of V - w L: U-shaped and buoyant lines included)
Spans suspended(const CatenaryParameters& p, double invEA, double H, double V) {
  const double w = p.weight, L = p.length;
  const double rF = V / H, rA = (V - w * L) / H;
  const double sF = std::sqrt(1.0 + rF * rF), sA = std::sqrt(1.0 + rA * rA);
  const double dAsinh = std::asinh(rF) - std::asinh(rA);
  Spans s;
  s.x = H / w * dAsinh + H * L * invEA;
  s.z = H / w * (sF - sA) + (V * L - 0.5 * w * L * L) * invEA;
  s.xh = (dAsinh - (rF / sF - rA / sA)) / w + L * invEA;
  s.xv = (1.0 / sF - 1.0 / sA) / w;
  s.zh = s.xv;
  s.zv = (rF / sF - rA / sA) / w + L * invEA;
  return s;
}

// (p, 1/EA, H > 0, 0 <= V < w L) => spans of a line resting on the bed over LB = L - V/w, the
// friction CB w per unit length reducing the tension toward A (zero below LB - H/(CB w))
Spans touchingDown(const CatenaryParameters& p, double invEA, double H, double V) {
  const double w = p.weight, L = p.length, cb = p.friction;
  const double lb = L - V / w, r = V / H, sq = std::sqrt(1.0 + r * r);
  Spans s;
  s.x = lb + H / w * std::asinh(r) + H * L * invEA;
  s.xh = (std::asinh(r) - r / sq) / w + L * invEA;
  s.xv = (1.0 / sq - 1.0) / w;
  if (cb > 0.0) {
    const double a = lb - H / (cb * w);  // the point where the tension on the bed reaches zero
    s.x += 0.5 * cb * w * invEA * (-lb * lb + a * std::max(a, 0.0));
    s.xh += a > 0.0 ? -a * invEA : 0.0;
    s.xv += a > 0.0 ? H * invEA / w : cb * lb * invEA;
  }
  s.z = H / w * (sq - 1.0) + 0.5 * V * V / w * invEA;
  s.zh = (1.0 / sq - 1.0) / w;
  s.zv = r / sq / w + V * invEA / w;
  return s;
}

// (p, V) => the line rests on the bed at this fairlead vertical tension
bool restsOnBed(const CatenaryParameters& p, double V) {
  return p.seabed && p.weight > 0.0 && V < p.weight * p.length;
}

double inverseEA(const CatenaryParameters& p) {
  return std::isinf(p.ea) ? 0.0 : 1.0 / p.ea;
}

// (p, 1/EA, ZF >= 0) => unstretched length hanging vertically from B down to the bed, m
double hangingLength(const CatenaryParameters& p, double invEA, double zf) {
  return 2.0 * zf / (std::sqrt(1.0 + 2.0 * zf * p.weight * invEA) + 1.0);
}

// (a suspended or touching-down solution with hf, vf, profile) => anchor tension, laid length,
// touchdown point
void finish(const CatenaryParameters& p, double xf, CatenarySolution& s) {
  const double w = p.weight, L = p.length;
  if (s.profile == CatenaryProfile::Suspended) {
    s.ha = s.hf;
    s.va = s.vf - w * L;
    s.laidLength = 0.0;
    s.touchdownX = 0.0;
    return;
  }
  s.laidLength = L - s.vf / w;
  s.ha = std::max(0.0, s.hf - p.friction * w * s.laidLength);
  s.va = 0.0;
  s.touchdownX = catenaryPoint(p, s, xf, s.laidLength).x;
}

}  // namespace

const char* catenaryParameterError(const CatenaryParameters& p) {
  if (!(std::isfinite(p.length) && p.length > 0.0)) return "the length must be finite and > 0";
  if (!(p.ea > 0.0)) return "EA must be > 0 (it may be infinite)";
  if (!(std::isfinite(p.weight) && p.weight != 0.0))
    return "the weight per length must be finite and nonzero (< 0: buoyant)";
  if (!(std::isfinite(p.friction) && p.friction >= 0.0))
    return "the sea-bed friction coefficient must be finite and >= 0";
  return "";
}

CatenarySolution solveCatenary(const CatenaryParameters& p, double xf, double zf, double hf0,
                               double vf0) {
  CatenarySolution sol;
  if (*catenaryParameterError(p) != '\0' || !(xf >= 0.0) || !std::isfinite(xf) ||
      !std::isfinite(zf))
    return sol;  // BadInput
  const double w = p.weight, L = p.length, invEA = inverseEA(p);
  const bool bed = p.seabed && w > 0.0;
  // (B at or below the bed) => below it: refused; on it: the closed forms of a line on the bed
  if (bed && zf <= 0.0) {
    if (zf < -1e-9 * L) {
      sol.status = CatenaryStatus::BelowSeabed;
      return sol;
    }
    zf = 0.0;
  }
  // (the line longer than XF plus its hanging length) => slack: it hangs under B, HF = 0
  if (bed && L >= xf + hangingLength(p, invEA, zf)) {
    const double lh = hangingLength(p, invEA, zf);
    sol.profile = CatenaryProfile::Slack;
    sol.hf = 0.0;
    sol.vf = w * lh;
    sol.ha = sol.va = 0.0;
    sol.laidLength = L - lh;
    sol.touchdownX = xf;
    sol.k22 = w / std::sqrt(1.0 + 2.0 * zf * w * invEA);
    sol.status = CatenaryStatus::Converged;
    return sol;
  }
  if (bed && zf == 0.0) {
    // (taut on the bed) => H from the stretch: H L/EA - CB w L^2/(2 EA) = XF - L while the
    // anchor holds tension, else H^2/(2 CB w EA) = XF - L
    sol.profile = CatenaryProfile::OnSeabed;
    if (invEA == 0.0) return sol;  // an inextensible line cannot be longer than itself: BadInput
    const double cbw = p.friction * w, stretch = (xf / L - 1.0) * p.ea;
    if (cbw == 0.0 || stretch >= 0.5 * cbw * L) {
      sol.hf = stretch + 0.5 * cbw * L;
      sol.k11 = p.ea / L;
    } else {
      sol.hf = std::sqrt(2.0 * p.ea * cbw * (xf - L));
      sol.k11 = p.ea * cbw / sol.hf;
    }
    sol.vf = 0.0;
    sol.k22 = w;  // lifting B off the bed: the weight of the line lifted per metre (approximate)
    sol.ha = std::max(0.0, sol.hf - cbw * L);
    sol.laidLength = L;
    sol.touchdownX = xf;
    sol.status = CatenaryStatus::Converged;
    return sol;
  }
  // (cold start) => the guess of Peyrot and Goulois (1979), as FAST v7 and MoorPy use it
  double H = hf0, V = vf0;
  if (!(H > 0.0) || !std::isfinite(V)) {
    const double chord = std::sqrt(xf * xf + zf * zf);
    const double lambda = xf <= 0.0    ? 1e6
                          : L <= chord ? 0.2
                                       : std::sqrt(3.0 * ((L * L - zf * zf) / (xf * xf) - 1.0));
    H = std::max(std::abs(0.5 * w * xf / lambda), 1e-8 * std::abs(w) * L);
    V = 0.5 * w * (zf / std::tanh(lambda) + L);
  }
  auto spans = [&](double h, double v) {
    return bed && v < w * L ? touchingDown(p, invEA, h, v) : suspended(p, invEA, h, v);
  };
  auto residual = [&](const Spans& s) { return std::abs(s.x - xf) + std::abs(s.z - zf); };
  const double tolR = 1e-12 * (L + xf + std::abs(zf));
  Spans s = spans(H, V);
  double res = residual(s);
  sol.status = CatenaryStatus::NoConvergence;
  for (int it = 1; it <= 100; ++it) {
    // (J, r) => the Newton step, H kept above a tenth of itself, halved while r grows
    const double det = s.xh * s.zv - s.xv * s.zh;
    const double rx = s.x - xf, rz = s.z - zf;
    const double dH = -(s.zv * rx - s.xv * rz) / det;
    const double dV = -(-s.zh * rx + s.xh * rz) / det;
    if (!std::isfinite(dH) || !std::isfinite(dV)) break;
    double alpha = dH < -0.9 * H ? -0.9 * H / dH : 1.0;
    double h1 = H + alpha * dH, v1 = V + alpha * dV;
    Spans s1 = spans(h1, v1);
    double res1 = residual(s1);
    for (int k = 0; k < 30 && !(res1 < res) && res > tolR; ++k) {
      alpha *= 0.5;
      h1 = H + alpha * dH;
      v1 = V + alpha * dV;
      s1 = spans(h1, v1);
      res1 = residual(s1);
    }
    // (a step below 1e-13 of the forces, full or cut by the line search) => at the rounding floor
    // of the spans (which a very taut, nearly inextensible line raises above tolR): converged if
    // the residual is within 1e-9 of the spans, else stuck
    const bool atFloor = std::abs(alpha * dH) + std::abs(alpha * dV) <= 1e-13 * (H + std::abs(V));
    H = h1;
    V = v1;
    s = s1;
    res = res1;
    sol.iterations = it;
    if (res <= tolR || (atFloor && res <= 1e3 * tolR)) {
      sol.status = CatenaryStatus::Converged;
      break;
    }
    if (atFloor) break;  // stuck: NoConvergence
  }
  // (H, V, J at the solution) => the stiffness J^-1 and the rest of the solution
  sol.hf = H;
  sol.vf = V;
  const double det = s.xh * s.zv - s.xv * s.zh;
  sol.k11 = s.zv / det;
  sol.k12 = -s.xv / det;
  sol.k21 = -s.zh / det;
  sol.k22 = s.xh / det;
  sol.profile = restsOnBed(p, V) ? CatenaryProfile::TouchingDown : CatenaryProfile::Suspended;
  finish(p, xf, sol);
  return sol;
}

CatenaryPoint catenaryPoint(const CatenaryParameters& p, const CatenarySolution& sol, double xf,
                            double s) {
  const double w = p.weight, L = p.length, invEA = inverseEA(p), H = sol.hf, V = sol.vf;
  CatenaryPoint pt;
  s = std::clamp(s, 0.0, L);
  switch (sol.profile) {
    case CatenaryProfile::Suspended: {
      // (s from A, V(s) = VA + w s) => Irvine's profile
      const double va = V - w * L, vs = va + w * s;
      pt.x = H / w * (std::asinh(vs / H) - std::asinh(va / H)) + H * s * invEA;
      pt.z = (std::sqrt(H * H + vs * vs) - std::sqrt(H * H + va * va)) / w +
             (va * s + 0.5 * w * s * s) * invEA;
      pt.tension = std::sqrt(H * H + vs * vs);
      return pt;
    }
    case CatenaryProfile::Slack: {
      // (on the bed up to XF, then hanging straight up to B) => the line bunched at B's foot
      const double lb = sol.laidLength;
      if (s <= lb) {
        pt.x = std::min(s, xf);
        return pt;
      }
      const double u = s - lb;
      pt.x = xf;
      pt.z = u + 0.5 * w * u * u * invEA;
      pt.tension = w * u;
      return pt;
    }
    case CatenaryProfile::TouchingDown:
    case CatenaryProfile::OnSeabed: {
      const double lb = sol.laidLength, cbw = p.friction * w;
      // (s on the bed) => x = s + integral of T/EA; T = H without friction, else
      // max(0, H - CB w (LB - s)), zero below xB = LB - H/(CB w)
      auto onBed = [&](double u, double& x, double& t) {
        if (cbw == 0.0) {
          t = H;
          x = u + H * u * invEA;
          return;
        }
        const double xb = lb - H / cbw;
        t = std::max(0.0, H - cbw * (lb - u));
        const double a = std::max(u - xb, 0.0), b = std::max(-xb, 0.0);
        x = u + 0.5 * cbw * invEA * (a * a - b * b);
      };
      if (s <= lb) {
        onBed(s, pt.x, pt.tension);
        return pt;
      }
      double xlb = 0.0, tlb = 0.0;
      onBed(lb, xlb, tlb);
      const double u = s - lb, vs = w * u;
      pt.x = xlb + H / w * std::asinh(vs / H) + H * u * invEA;
      pt.z = (std::sqrt(H * H + vs * vs) - H) / w + 0.5 * w * u * u * invEA;
      pt.tension = std::sqrt(H * H + vs * vs);
      return pt;
    }
  }
  return pt;
}

double catenaryEnergy(const CatenaryParameters& p, const CatenarySolution& sol) {
  const double w = p.weight, L = p.length, invEA = inverseEA(p), H = sol.hf, V = sol.vf;
  // (H, u) => integral of sqrt(H^2 + u^2) du
  auto G = [H](double u) {
    const double r = std::sqrt(H * H + u * u);
    return 0.5 * u * r + (H > 0.0 ? 0.5 * H * H * std::asinh(u / H) : 0.0);
  };
  switch (sol.profile) {
    case CatenaryProfile::Suspended: {
      const double va = V - w * L, ta = std::sqrt(H * H + va * va);
      const double zInt =
          (G(V) - G(va)) / (w * w) - L * ta / w + (0.5 * va * L * L + w * L * L * L / 6.0) * invEA;
      const double strain = 0.5 * invEA * (H * H * L + (V * V * V - va * va * va) / (3.0 * w));
      return w * zInt + strain;
    }
    case CatenaryProfile::Slack: {
      const double lh = L - sol.laidLength;
      return w * (0.5 * lh * lh + w * lh * lh * lh / 6.0 * invEA) +
             w * w * lh * lh * lh / 6.0 * invEA;
    }
    case CatenaryProfile::TouchingDown:
    case CatenaryProfile::OnSeabed: {
      const double lb = sol.laidLength, ls = L - lb, cbw = p.friction * w;
      const double zInt = (G(V) - G(0.0)) / (w * w) - ls * H / w + w * ls * ls * ls / 6.0 * invEA;
      double strain = 0.5 * invEA * (H * H * ls + V * V * V / (3.0 * w));
      // (T on the bed) => integral of T^2 / (2 EA)
      if (cbw == 0.0) {
        strain += 0.5 * invEA * H * H * lb;
      } else {
        const double ta = std::max(0.0, H - cbw * lb);
        strain += 0.5 * invEA * (H * H * H - ta * ta * ta) / (3.0 * cbw);
      }
      return w * zInt + strain;
    }
  }
  return 0.0;
}

}  // namespace yardsim::forces
