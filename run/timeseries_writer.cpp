#include "run/timeseries_writer.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace yardsim::run {

using models::Channel;
using scene::Scene;

const char* const kVersion = YARDSIM_VERSION;

void appendCsvNumber(std::string& out, double value) {
  if (std::isnan(value)) {
    out += "nan";
    return;
  }
  char buf[32];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
  out.append(buf, ec == std::errc() ? end : buf);
}

TimeseriesWriter::TimeseriesWriter(const std::filesystem::path& file, const Scene& scene,
                                   std::vector<Channel> channels,
                                   const std::string& restartedFrom)
    : out_(file), channels_(std::move(channels)), lastFlush_(std::chrono::steady_clock::now()) {
  if (!out_) throw std::runtime_error("cannot write '" + file.string() + "'");
  out_ << "# yardsim " << kVersion << "\n"
       << "# scene " << scene.file.string() << "\n"
       << "# scene_sha256 " << scene.sha256 << "\n"
       << "# integrator " << scene.integrator << "\n"
       << "# step " << scene.dt << "\n"
       << "# seed " << scene.seed << "\n";
  if (!restartedFrom.empty()) out_ << "# restarted_from " << restartedFrom << "\n";
  out_ << "time[s]";
  for (const auto& c : channels_) out_ << ',' << c.column();
  out_ << '\n';
  out_.flush();
}

TimeseriesWriter::~TimeseriesWriter() { out_.flush(); }

void TimeseriesWriter::sample(double t) {
  line_.clear();
  appendCsvNumber(line_, t);
  for (const auto& c : channels_) {
    line_ += ',';
    appendCsvNumber(line_, c.read());
  }
  line_ += '\n';
  out_ << line_;
  ++rows_;
  const auto now = std::chrono::steady_clock::now();
  if (now - lastFlush_ > std::chrono::milliseconds(200)) {
    out_.flush();
    lastFlush_ = now;
  }
}

}  // namespace yardsim::run
