// peer_cadmium_devstone VARIANT DEPTH WIDTH
// Cadmium v2 running its own DEVStone (example/devstone of SimulationEverywhere/cadmium_v2,
// compiled from the peers' folder, never copied here), timed and reported exactly like
// bench/devstone/devstone (devstone_report.hpp): build = the model's construction, the
// RootCoordinator and start(), sim = simulate(infinity). The transition counts are checked
// against yardsim's closed forms (exit 1 on a mismatch), so both run the same model.
#include <chrono>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>

#include "devstone.hpp"
#include "devstone_report.hpp"

int main(int argc, char** argv) {
  namespace ds = yardsim::bench::devstone;
  using Clock = std::chrono::steady_clock;
  if (argc != 4) {
    std::fprintf(stderr, "usage: peer_cadmium_devstone LI|HI|HO|HOmod DEPTH WIDTH\n");
    return 2;
  }
  try {
    const std::string type = argv[1];
    const int depth = std::stoi(argv[2]), width = std::stoi(argv[3]);
    const ds::Variant variant = ds::parseVariant(type);
    // () => the model built, the coordinators made and started
    const long f0 = ds::minorFaults();
    const double c0 = ds::cpuSeconds();
    const auto t0 = Clock::now();
    auto model = std::make_shared<cadmium::example::devstone::DEVStone>(type, width, depth, 0, 0);
    cadmium::RootCoordinator root(model);
    root.start();
    const auto t1 = Clock::now();
    const double c1 = ds::cpuSeconds();
    const long f1 = ds::minorFaults();
    // () => every event executed
    root.simulate(std::numeric_limits<double>::infinity());
    const auto t2 = Clock::now();
    const double c2 = ds::cpuSeconds();
    const long f2 = ds::minorFaults();
    root.stop();
    ds::Counts got;
    got.atomics = static_cast<std::uint64_t>(model->nAtomics());
    got.internal = static_cast<std::uint64_t>(model->nInternals());
    got.external = static_cast<std::uint64_t>(model->nExternals());
    const ds::RunTimes t{std::chrono::duration<double>(t1 - t0).count(),
                         std::chrono::duration<double>(t2 - t1).count(),
                         c1 - c0,
                         c2 - c1,
                         f1 - f0,
                         -1,
                         f2 - f1};
    return ds::printRun("cadmium", type.c_str(), depth, width, got,
                        ds::expected(variant, depth, width), t)
               ? 0
               : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "peer_cadmium_devstone: error: %s\n", e.what());
    return 2;
  }
}
