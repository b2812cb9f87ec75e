// bench_report_size OUTDIR: a synthetic run's outputs at the size — timeseries.csv with
// 3 channels x 100,000 samples, replay.glb with 20 bodies x 2,000 poses — then report.html;
// prints the sizes and the wall time of writing the report.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "output/gltf_writer.hpp"
#include "output/report_writer.hpp"
#include "run/timeseries_writer.hpp"

using namespace yardsim;

int main(int argc, char** argv) {
  const std::filesystem::path out = argc > 1 ? argv[1] : "out/report_size";
  std::filesystem::create_directories(out);
  // (3 channels, 100,000 samples) => timeseries.csv
  double t = 0.0;
  {
    scene::Scene scene;
    scene.name = "report_size";
    std::vector<models::Channel> ch{
        {"crane1.hoist.tension", "N", [&] { return 4.5e6 * (1.0 + 0.1 * std::sin(3.0 * t)); }},
        {"crane2.hoist.tension", "N", [&] { return 4.4e6 * (1.0 + 0.1 * std::cos(2.0 * t)); }},
        {"block.roll", "rad", [&] { return 0.01 * t; }}};
    run::TimeseriesWriter w(out / "timeseries.csv", scene, ch);
    for (int k = 0; k < 100000; ++k) {
      t = 0.01 * k;
      w.sample(t);
    }
  }
  // (20 bodies, 2,000 poses) => replay.glb
  models::Replay r;
  for (int k = 0; k < 2000; ++k) r.times.push_back(0.5f * static_cast<float>(k));
  for (int b = 0; b < 20; ++b) {
    models::ReplayBody body;
    body.name = "body" + std::to_string(b);
    for (int k = 0; k < 2000; ++k) {
      const float a = 0.001f * static_cast<float>(k * (b + 1));
      body.translation.push_back({static_cast<float>(b) * 10.0f, std::sin(a), 0.01f * static_cast<float>(k)});
      body.rotation.push_back({0.0f, 0.0f, std::sin(a / 2), std::cos(a / 2)});
    }
    r.bodies.push_back(body);
  }
  output::writeGlb(r, out / "replay.glb");
  const auto start = std::chrono::steady_clock::now();
  output::writeReport(out);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  auto mb = [&](const char* f) { return static_cast<double>(std::filesystem::file_size(out / f)) / 1e6; };
  std::printf("timeseries.csv %.2f MB, replay.glb %.2f MB, report.html %.2f MB, written in %.3f s\n",
              mb("timeseries.csv"), mb("replay.glb"), mb("report.html"), wall);
}
