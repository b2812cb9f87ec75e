#include "forces/hydro/hydrodynamics_methods.hpp"

#include <cstdio>
#include <stdexcept>

#include "forces/hydro/impulse_response_cache.hpp"

namespace yardsim::forces::hydro {

namespace {
std::map<std::string, ImpulseResponseSolver>& solvers() {
  static std::map<std::string, ImpulseResponseSolver> all;
  return all;
}
std::map<std::string, TimeDomainMethod>& methods() {
  static std::map<std::string, TimeDomainMethod> all;
  return all;
}
}  // namespace

void registerImpulseResponseSolver(ImpulseResponseSolver solver) {
  const std::string name = solver.name;
  solvers()[name] = std::move(solver);
}

const ImpulseResponseSolver* impulseResponseSolver(const std::string& name) {
  if (name.empty()) return solvers().size() == 1 ? &solvers().begin()->second : nullptr;
  const auto it = solvers().find(name);
  return it == solvers().end() ? nullptr : &it->second;
}

std::vector<std::string> impulseResponseSolverNames() {
  std::vector<std::string> out;
  for (const auto& [name, s] : solvers()) out.push_back(name);
  return out;
}

void registerTimeDomainMethod(TimeDomainMethod method) {
  const std::string name = method.name;
  methods()[name] = std::move(method);
}

const TimeDomainMethod* timeDomainMethod(const std::string& name) {
  const auto it = methods().find(name);
  return it == methods().end() ? nullptr : &it->second;
}

std::string requestKey(const HydrodynamicsRequest& r, const std::string& solver) {
  std::uint64_t h = fnv1a(solver.data(), solver.size());
  const std::uint32_t format = kImpulseResponseFormat;  // another version is another key
  h = fnv1a(&format, sizeof format, h);
  auto doubles = [&](const double* x, std::size_t n) { h = fnv1a(x, n * sizeof(double), h); };
  if (r.hull) {
    for (const auto& v : r.hull->vertices) doubles(v.data(), 3);
    for (const auto& t : r.hull->triangles) h = fnv1a(t.data(), sizeof(int) * 3, h);
  }
  doubles(r.X_WB.R.data(), 9);
  doubles(r.X_WB.p.data(), 3);
  const double water[4] = {r.water.density, r.water.gravity, r.water.depth, r.water.level};
  doubles(water, 4);
  doubles(r.headings.data(), r.headings.size());
  const double steps[2] = {r.dt, r.memory};
  doubles(steps, 2);
  for (const auto& [name, value] : r.settings) {
    h = fnv1a(name.data(), name.size(), h);
    doubles(&value, 1);
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return solver + "-" + hex;
}

std::shared_ptr<const ImpulseResponse> cachedOrSolved(const HydrodynamicsRequest& request,
                                                      const ImpulseResponseSolver& solver,
                                                      const std::filesystem::path& cacheDir) {
  const std::string key = requestKey(request, solver.name);
  if (auto cached = loadCachedResponse(cacheDir, key))
    return std::make_shared<const ImpulseResponse>(std::move(*cached));
  ImpulseResponse ir = solver.solve(request);
  ir.key = key;
  writeImpulseResponse(ir, cacheFile(cacheDir, key));
  return std::make_shared<const ImpulseResponse>(std::move(ir));
}

}  // namespace yardsim::forces::hydro
