// peer_adevs_devstone VARIANT DEPTH WIDTH
// adevs 3.3 running the DEVStone models written for it in SimulationEverywhere/devstone-comparative
// (devstone/adevs/src, compiled from the peers' folder, never copied here), timed and reported
// exactly like bench/devstone/devstone (devstone_report.hpp): build = the model's construction and
// adevs::Simulator's set-up, sim = execNextEvent until nothing is scheduled. The transition counts
// are checked against yardsim's closed forms (exit 1 on a mismatch), so both run the same model.
#include <cfloat>
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <string>

using namespace std;  // devstone-comparative's headers use string and runtime_error unqualified
#include "devstone.hpp"
#include "devstone_report.hpp"

int main(int argc, char** argv) {
  namespace ds = yardsim::bench::devstone;
  using Clock = std::chrono::steady_clock;
  if (argc != 4) {
    std::fprintf(stderr, "usage: peer_adevs_devstone LI|HI|HO|HOmod DEPTH WIDTH\n");
    return 2;
  }
  try {
    const std::string type = argv[1];
    const int depth = std::stoi(argv[2]), width = std::stoi(argv[3]);
    const ds::Variant variant = ds::parseVariant(type);
    // () => the model built and the simulator set up
    const long f0 = ds::minorFaults();
    const double c0 = ds::cpuSeconds();
    const auto t0 = Clock::now();
    auto* model = new DEVStone(type, width, depth, 0, 0);
    adevs::Simulator<IO_Type> sim(model);
    const auto t1 = Clock::now();
    const double c1 = ds::cpuSeconds();
    const long f1 = ds::minorFaults();
    // () => every event executed
    while (sim.nextEventTime() < DBL_MAX) sim.execNextEvent();
    const auto t2 = Clock::now();
    const double c2 = ds::cpuSeconds();
    const long f2 = ds::minorFaults();
    ds::Counts got;
    got.atomics = model->model->nAtomics();
    got.internal = model->model->nInternals();
    got.external = model->model->nExternals();
    const ds::RunTimes t{std::chrono::duration<double>(t1 - t0).count(),
                         std::chrono::duration<double>(t2 - t1).count(),
                         c1 - c0,
                         c2 - c1,
                         f1 - f0,
                         -1,
                         f2 - f1};
    return ds::printRun("adevs", type.c_str(), depth, width, got,
                        ds::expected(variant, depth, width), t)
               ? 0
               : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "peer_adevs_devstone: error: %s\n", e.what());
    return 2;
  }
}
