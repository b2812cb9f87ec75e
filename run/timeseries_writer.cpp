#include "run/timeseries_writer.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "devs/shortest_text.hpp"

namespace yardsim::run {

using models::Channel;
using scene::Scene;

const char* const kVersion = YARDSIM_VERSION;

void appendCsvNumber(std::string& out, double value) {
  if (std::isnan(value)) {
    out += "nan";
    return;
  }
  char buf[devs::kShortestTextSize];
  out.append(buf, devs::writeShortest(buf, value));
}

TimeseriesWriter::TimeseriesWriter(const std::filesystem::path& file, const Scene& scene,
                                   std::vector<Channel> channels, const std::string& restartedFrom)
    : file_(file), channels_(std::move(channels)), lastFlush_(std::chrono::steady_clock::now()) {
  if (!out_) throw std::runtime_error("cannot write '" + file.string() + "'");
  last_.assign(channels_.size(), {});
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
  for (std::size_t i = 0; i < channels_.size(); ++i) {
    line_ += ',';
    // (value) => the previous row's text again when the bits are the same, else converted
    const double v = channels_[i].read();
    const auto bits = std::bit_cast<std::uint64_t>(v);
    Cell& cell = last_[i];
    if (cell.length != 0 && cell.bits == bits) {
      line_.append(cell.text, cell.length);
      continue;
    }
    const std::size_t at = line_.size();
    appendCsvNumber(line_, v);
    const std::size_t n = line_.size() - at;
    cell.length = static_cast<unsigned char>(n <= sizeof cell.text ? n : 0);
    if (cell.length != 0) line_.copy(cell.text, n, at);
    cell.bits = bits;
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
