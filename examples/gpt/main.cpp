// Runs the generator-processor-transducer model and writes its event trace:
//   gpt OUTDIR [--period P] [--processing T] [--observe T]
// => OUTDIR/trace.jsonl, OUTDIR/trace.json (Chrome/Perfetto), OUTDIR/trace.csv
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>

#include "devs/chrome_trace_sink.hpp"
#include "devs/csv_trace_sink.hpp"
#include "devs/jsonl_trace_sink.hpp"
#include "devs/simulator.hpp"
#include "gpt_models.hpp"

int main(int argc, char** argv) {
  using namespace yardsim;
  CLI::App app{"Generator-processor-transducer DEVS example; writes its event trace"};
  std::filesystem::path outdir = "out/gpt";
  examples::gpt::Parameters p;
  app.add_option("outdir", outdir, "output folder")->capture_default_str();
  app.add_option("--period", p.period, "seconds between jobs")->capture_default_str();
  app.add_option("--processing", p.processing, "seconds per job")->capture_default_str();
  app.add_option("--observe", p.observe, "observation time, s")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  try {
    std::filesystem::create_directories(outdir);
    auto model = examples::gpt::makeGpt(p);
    devs::Simulator sim(*model);
    devs::JsonlTraceSink jsonl(devs::TraceStream(outdir / "trace.jsonl"));
    devs::ChromeTraceSink chrome(devs::TraceStream(outdir / "trace.json"));
    devs::CsvTraceSink csv(devs::TraceStream(outdir / "trace.csv"));
    sim.addListener(jsonl);
    sim.addListener(chrome);
    sim.addListener(csv);
    sim.run();
    chrome.close();

    const auto& transd = static_cast<const examples::gpt::Transducer&>(
        *static_cast<devs::Coupled&>(*model->findComponent("ef")).findComponent("transd"));
    std::printf("gpt: t_end = %g s, %llu transitions\n", sim.time(),
                static_cast<unsigned long long>(sim.stats().internal + sim.stats().external +
                                                sim.stats().confluent));
    std::printf("gpt: arrived %d, solved %d, throughput %.4f jobs/s, mean turnaround %.3f s\n",
                transd.state().arrived, transd.state().solved, transd.throughput(),
                transd.meanTurnaround());
    std::printf("gpt: trace written to %s/trace.{jsonl,json,csv}\n", outdir.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gpt: error: %s\n", e.what());
    return 3;
  }
  return 0;
}
