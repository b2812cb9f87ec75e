// devstone --variant LI|HI|HO|HOmod --depth D --width W
// Builds and runs one DEVStone model and prints one JSON line: variant, depth, width,
// atomics, internal, external, expected counts, build_seconds (model construction and
// flattening), sim_seconds, transitions_per_second (of the simulation phase), counts_ok, and
// the same two phases in process CPU time (build_cpu_seconds, sim_cpu_seconds), which a busy
// machine disturbs less than wall time.
// Exit status 1 when the counts differ from the closed form.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <ctime>

#include "devs/simulator.hpp"
#include "devstone_models.hpp"

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
  auto cpu = [] {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
  };
  try {
    const auto variant = bench::devstone::parseVariant(variantName);
    const double c0 = cpu();
    const auto t0 = Clock::now();
    auto root = bench::devstone::build(variant, depth, width);
    devs::Simulator sim(*root);
    devs::Listener nullListener;
    if (hooks) sim.addListener(nullListener);
    const auto t1 = Clock::now();
    const double c1 = cpu();
    sim.run();
    const auto t2 = Clock::now();
    const double c2 = cpu();
    const auto got = bench::devstone::count(*root);
    const auto want = bench::devstone::expected(variant, depth, width);
    const double build = std::chrono::duration<double>(t1 - t0).count();
    const double simulate = std::chrono::duration<double>(t2 - t1).count();
    const bool ok = got.internal == want.internal && got.external == want.external &&
                    got.atomics == want.atomics;
    std::printf(
        "{\"variant\":\"%s\",\"depth\":%d,\"width\":%d,\"atomics\":%llu,\"internal\":%llu,"
        "\"external\":%llu,\"expected\":%llu,\"build_seconds\":%.6f,\"sim_seconds\":%.6f,"
        "\"transitions_per_second\":%.0f,\"counts_ok\":%s,\"build_cpu_seconds\":%.6f,"
        "\"sim_cpu_seconds\":%.6f}\n",
        variantName.c_str(), depth, width, static_cast<unsigned long long>(got.atomics),
        static_cast<unsigned long long>(got.internal),
        static_cast<unsigned long long>(got.external),
        static_cast<unsigned long long>(want.internal), build, simulate,
        simulate > 0 ? static_cast<double>(got.internal + got.external) / simulate : 0.0,
        ok ? "true" : "false", c1 - c0, c2 - c1);
    return ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "devstone: error: %s\n", e.what());
    return 2;
  }
}
