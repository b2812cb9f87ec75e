#include "forces/geometry/submerged_mesh.hpp"

#include <algorithm>
#include <limits>
#include <utility>

namespace yardsim::forces {

using dynamics::Vector3;

SubmergedWorkspace::SubmergedWorkspace(const TriangleMesh& mesh, std::size_t components)
    : vertices(mesh.vertices.size()),
      depth(mesh.vertices.size()),
      wet(2 * mesh.triangles.size()),
      edge(3 * mesh.triangles.size()),
      halfPhase(2 * components * mesh.vertices.size()) {
  // (triangles) => one number per unordered pair of corners: sort the 3 T (pair, slot) and number
  // the runs of equal pairs
  std::vector<std::pair<std::pair<int, int>, std::size_t>> ends;
  ends.reserve(edge.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (std::size_t e = 0; e < 3; ++e) {
      const int i = mesh.triangles[t][e], j = mesh.triangles[t][(e + 1) % 3];
      ends.push_back({{std::min(i, j), std::max(i, j)}, 3 * t + e});
    }
  std::sort(ends.begin(), ends.end());
  int n = -1;
  for (std::size_t k = 0; k < ends.size(); ++k) {
    if (k == 0 || ends[k].first != ends[k - 1].first) ++n;
    edge[ends[k].second] = n;
  }
  edgePressure.assign(static_cast<std::size_t>(n + 1), 0.0);
  edgeStamp.assign(static_cast<std::size_t>(n + 1), 0U);
}

namespace {

// (as integrateSubmerged; kAll false: the force and moment alone) => submerged properties
template <bool kAll>
SubmergedProperties integrate(const TriangleMesh& mesh, const dynamics::Transform& X_WB,
                              const AiryWaves& sea, double t, SubmergedWorkspace& ws,
                              bool keepWet) {
  // (X_WB, surface) => corners in the world and their depth below the surface; in waves, each
  // corner's half phases first (the surface there from them, and later its edges' midpoints),
  // except for a corner above the highest crest the sea can reach at t (with a margin for
  // round-off): dry, its depth kAbove until a crossing edge asks for it (depthOf)
  const std::size_t nv = mesh.vertices.size();
  const std::size_t m2 = 2 * sea.size();
  const double ramp = sea.ramp(t);  // once for every point of this call
  const bool waves = !sea.calm() && ramp > 0.0;
  if (waves && ws.halfPhase.size() < m2 * nv) ws.halfPhase.resize(m2 * nv);
  constexpr double kAbove = -std::numeric_limits<double>::infinity();
  double crest = std::numeric_limits<double>::infinity();
  if (waves) {
    double amplitudes = 0.0;
    for (std::size_t i = 0; i < sea.size(); ++i) amplitudes += 0.5 * sea.component(i).height;
    crest = sea.water().level + ramp * amplitudes * (1.0 + 1e-12) + 1e-9;
  }
  // (corner i in the world, waves) => its half phases and its depth
  const auto waveDepth = [&](std::size_t i, const Vector3& p) {
    double* h = ws.halfPhase.data() + m2 * i;
    sea.halfPhases(p.x(), p.y(), t, h);
    return sea.elevationRamped(h, ramp) - p.z();
  };
  for (std::size_t i = 0; i < nv; ++i) {
    const Vector3 p = X_WB.actPoint(mesh.vertices[i]);
    ws.vertices[i] = p;
    if (!waves)
      ws.depth[i] = sea.water().level - p.z();
    else
      ws.depth[i] = p.z() > crest ? kAbove : waveDepth(i, p);
  }
  // (corner i) => its depth, computed now for a corner above the crests
  const auto depthOf = [&](std::size_t i) {
    if (ws.depth[i] == kAbove) ws.depth[i] = waveDepth(i, ws.vertices[i]);
    return ws.depth[i];
  };
  // apex of the tetrahedra: on the surface above the body origin (on the plane in calm water,
  // where the waterplane's own tetrahedra vanish)
  const Vector3 o(
      X_WB.p.x(), X_WB.p.y(),
      !kAll || sea.calm() ? sea.water().level : sea.elevation(X_WB.p.x(), X_WB.p.y(), t));
  // (a new call) => every cached edge pressure stale
  if (++ws.call == 0) {
    std::fill(ws.edgeStamp.begin(), ws.edgeStamp.end(), 0U);
    ws.call = 1;
  }
  SubmergedProperties r;
  double vol6 = 0.0, wpA = 0.0, wpX = 0.0, wpY = 0.0, wpXX = 0.0, wpYY = 0.0, wpXY = 0.0;
  Vector3 first = Vector3::Zero(), F = Vector3::Zero(), M = Vector3::Zero();
  // (wetted piece a, b, c; pressureOf(q, side) the pressure at the midpoint q of its side from
  // a, b, c to b, c, a) => its share of every integral. The force and moment: in calm water
  // -p_i / 3 S and -p_i / 3 q_i x S for each side; in waves, where the pressures cost more than
  // these products, 3 F = -(sum p_i) S and 3 M = -(sum p_i q_i) x S (one cross product)
  const auto piece = [&](const Vector3& a, const Vector3& b, const Vector3& c, auto&& pressureOf) {
    const Vector3 S = 0.5 * (b - a).cross(c - a);  // outward area vector
    const Vector3 m[3] = {0.5 * (a + b), 0.5 * (b + c), 0.5 * (c + a)};
    double pSum = 0.0;
    Vector3 pq = Vector3::Zero();
    if constexpr (kAll) {
      const Vector3 ao = a - o, bo = b - o, co = c - o;
      const double d6 = ao.dot(bo.cross(co));
      vol6 += d6;
      first += d6 * (ao + bo + co);  // / 24 later
    }
    for (int side = 0; side < 3; ++side) {
      const Vector3& q = m[side];
      // waterplane by the divergence theorem on (0, 0, f(x, y)): int_cap f = -sum f n_z dS
      if constexpr (kAll) {
        const double w = -S.z() / 3.0;
        wpA += w;
        wpX += w * q.x();
        wpY += w * q.y();
        wpXX += w * q.x() * q.x();
        wpYY += w * q.y() * q.y();
        wpXY += w * q.x() * q.y();
      }
      const double p = pressureOf(q, side);
      if (!waves) {
        F -= p / 3.0 * S;
        M -= p / 3.0 * q.cross(S);
      } else {
        pSum += p;
        pq += p * q;
      }
    }
    if (waves) {
      F -= pSum * S;
      M -= pq.cross(S);
    }
    if constexpr (kAll) r.wettedArea += S.norm();
    if (keepWet) ws.wet[static_cast<std::size_t>(r.wetTriangles++)] = {a, b, c};
  };
  for (std::size_t ti = 0; ti < mesh.triangles.size(); ++ti) {
    const auto& tri = mesh.triangles[ti];
    // (mesh edge e of the triangle, midpoint q of its wet part, t) => the incident pressure there,
    // once per call for every triangle on the edge: a wholly wet edge's midpoint 0.5 (a + b) in
    // waves from its corners' half phases, a crossing one's (between its wet corner and the
    // crossing, the same double vector in both triangles in waves) directly
    const auto edgePressure = [&](const Vector3& q, int e, bool whole) {
      if (!waves) return sea.hydrostaticPressure(q);
      const auto k = static_cast<std::size_t>(ws.edge[3 * ti + static_cast<std::size_t>(e)]);
      if (ws.edgeStamp[k] != ws.call) {
        const auto a = static_cast<std::size_t>(tri[static_cast<std::size_t>(e)]);
        const auto b = static_cast<std::size_t>(tri[static_cast<std::size_t>((e + 1) % 3)]);
        ws.edgePressure[k] = whole ? sea.pressureBetween(q, ws.halfPhase.data() + m2 * a,
                                                         ws.halfPhase.data() + m2 * b, t, ramp)
                                   : sea.pressure(q, t, ramp);
        ws.edgeStamp[k] = ws.call;
      }
      return ws.edgePressure[k];
    };
    // (corner depths) => dry: nothing; wholly wet: the triangle itself, every side a mesh edge
    const auto i0 = static_cast<std::size_t>(tri[0]), i1 = static_cast<std::size_t>(tri[1]),
               i2 = static_cast<std::size_t>(tri[2]);
    const bool w0 = ws.depth[i0] > 0.0, w1 = ws.depth[i1] > 0.0, w2 = ws.depth[i2] > 0.0;
    if (!w0 && !w1 && !w2) continue;
    if (w0 && w1 && w2) {
      piece(ws.vertices[i0], ws.vertices[i1], ws.vertices[i2],
            [&](const Vector3& q, int side) { return edgePressure(q, side, true); });
      continue;
    }
    // (else) => the wetted polygon (Sutherland-Hodgman against depth > 0), 3 or 4 corners, and
    // for each the triangle's corner e it is, or -1 - e for a point where edge e (from corner e
    // to e + 1) crosses the surface. In waves the crossing is interpolated from the edge's end
    // with the lower vertex number: the same double vector in both triangles on the edge
    Vector3 poly[4];
    int corner[4];
    int n = 0;
    for (int e = 0; e < 3; ++e) {
      const auto i = static_cast<std::size_t>(tri[static_cast<std::size_t>(e)]);
      const auto j = static_cast<std::size_t>(tri[static_cast<std::size_t>((e + 1) % 3)]);
      const double di = ws.depth[i], dj = ws.depth[j];
      if (di > 0.0) {
        corner[n] = e;
        poly[n++] = ws.vertices[i];
      }
      if ((di > 0.0) != (dj > 0.0)) {
        const double a = depthOf(i), b = depthOf(j);
        corner[n] = -1 - e;
        poly[n++] = waves && j < i
                        ? Vector3(ws.vertices[j] + b / (b - a) * (ws.vertices[i] - ws.vertices[j]))
                        : Vector3(ws.vertices[i] + a / (a - b) * (ws.vertices[j] - ws.vertices[i]));
      }
    }
    // (midpoint q of the piece's side from polygon corner u to w, at t) => the incident pressure:
    // per mesh edge as above for a side along one (a crossing's side in waves only: in calm water
    // the two triangles' crossings differ in their last bits, and the pressure is cheap); the
    // diagonal of a four-cornered polygon, a side of both its pieces, once
    double diagonal = 0.0;
    const auto pressureAt = [&](const Vector3& q, int u, int w) {
      if (!waves) return sea.hydrostaticPressure(q);
      const int cu = corner[u], cw = corner[w];
      if (cu >= 0 && cw >= 0) return edgePressure(q, (cu + 1) % 3 == cw ? cu : cw, true);
      if (n == 4 && (u ^ w) == 2) {  // (0, 2) or (2, 0): the first piece's last side comes first
        if (u == 2) diagonal = sea.pressure(q, t, ramp);
        return diagonal;
      }
      if ((cu >= 0) != (cw >= 0)) return edgePressure(q, -1 - std::min(cu, cw), false);
      return sea.pressure(q, t, ramp);
    };
    for (int k = 1; k + 1 < n; ++k) {
      const int from[3] = {0, k, k + 1}, to[3] = {k, k + 1, 0};
      piece(poly[0], poly[k], poly[k + 1],
            [&](const Vector3& q, int side) { return pressureAt(q, from[side], to[side]); });
    }
  }
  r.force = waves ? Vector3(F / 3.0) : F;
  r.moment = waves ? Vector3(M / 3.0) : M;
  if constexpr (!kAll) return r;
  r.volume = vol6 / 6.0;
  r.centreOfBuoyancy = r.volume > 0.0 ? Vector3(o + first / (4.0 * vol6)) : o;
  r.waterplaneArea = wpA;
  if (wpA > 0.0) {
    const double xc = wpX / wpA, yc = wpY / wpA;
    r.waterplaneCentroid = Eigen::Vector2d(xc, yc);
    r.waterplaneInertia << wpXX - wpA * xc * xc, wpXY - wpA * xc * yc, wpXY - wpA * xc * yc, wpYY - wpA * yc * yc;
  } else {
    r.waterplaneCentroid = o.head<2>();
  }
  return r;
}

}  // namespace

SubmergedProperties integrateSubmerged(const TriangleMesh& mesh, const dynamics::Transform& X_WB,
                                       const AiryWaves& sea, double t, SubmergedWorkspace& ws,
                                       bool keepWet, SubmergedIntegrals which) {
  return which == SubmergedIntegrals::All ? integrate<true>(mesh, X_WB, sea, t, ws, keepWet)
                                          : integrate<false>(mesh, X_WB, sea, t, ws, keepWet);
}

}  // namespace yardsim::forces
