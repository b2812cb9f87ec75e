// devstone --variant LI|HI|HO|HOmod --depth D --width W
// Builds and runs one DEVStone model and prints one JSON line (devstone_report.hpp): simulator,
// variant, depth, width, atomics, internal, external, expected counts, build_seconds (model
// construction and flattening), sim_seconds, transitions_per_second (of the simulation phase),
// counts_ok, and the same two phases in process CPU time (build_cpu_seconds, sim_cpu_seconds),
// which a busy machine disturbs less than wall time, and the minor page faults of the model's
// construction, the Simulator's set-up and the simulation (build_faults, setup_faults,
// sim_faults). Exit status 1 when the counts differ from the
// closed form.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>

#include "devs/simulator.hpp"
#include "devstone_models.hpp"
#include "devstone_report.hpp"

int main(int argc, char** argv) {
  using namespace yardsim;
  using Clock = std::chrono::steady_clock;
  CLI::App app{"DEVStone benchmark of the yardsim DEVS simulator"};
  std::string variantName = "HI";
  int depth = 10, width = 10;
  app.add_option("--variant", variantName, "LI, HI, HO or HOmod")->capture_default_str();
  app.add_option("--depth", depth, "depth d >= 1")->capture_default_str();
  app.add_option("--width", width, "width w >= 1")->capture_default_str();
  bool hooks = false;
  app.add_flag("--null-listener", hooks,
               "attach a listener whose hooks do nothing (measures the cost of the trace hooks)");
  CLI11_PARSE(app, argc, argv);
  try {
    const auto variant = bench::devstone::parseVariant(variantName);
    const long f0 = bench::devstone::minorFaults();
    const double c0 = bench::devstone::cpuSeconds();
    const auto t0 = Clock::now();
    auto root = bench::devstone::build(variant, depth, width);
    const long f1 = bench::devstone::minorFaults();
    devs::Simulator sim(*root);
    devs::Listener nullListener;
    if (hooks) sim.addListener(nullListener);
    const auto t1 = Clock::now();
    const double c1 = bench::devstone::cpuSeconds();
    const long f2 = bench::devstone::minorFaults();
    sim.run();
    const auto t2 = Clock::now();
    const double c2 = bench::devstone::cpuSeconds();
    const long f3 = bench::devstone::minorFaults();
    const bench::devstone::RunTimes t{std::chrono::duration<double>(t1 - t0).count(),
                                      std::chrono::duration<double>(t2 - t1).count(),
                                      c1 - c0,
                                      c2 - c1,
                                      f1 - f0,
                                      f2 - f1,
                                      f3 - f2};
    const bool ok = bench::devstone::printRun("yardsim", variantName.c_str(), depth, width,
                                              bench::devstone::count(*root),
                                              bench::devstone::expected(variant, depth, width), t);
    return ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "devstone: error: %s\n", e.what());
    return 2;
  }
}
