#include <cstdio>
#include <filesystem>
#include <fstream>

#include <yaml-cpp/yaml.h>

#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "models/channels.hpp"

namespace yardsim::cli {

// (JSON Lines trace, globs, time window) => matching records, one aligned line each
int traceCommand(const TraceArgs& a) {
  // (path) => a regular file (a device such as /dev/zero has a line without end)
  std::error_code ec;
  if (std::filesystem::exists(a.file, ec) && !std::filesystem::is_regular_file(a.file, ec)) {
    std::fprintf(stderr, "yardsim trace: '%s' is not a regular file\n", a.file.c_str());
    return kInvalidInput;
  }
  std::ifstream in(a.file);
  if (!in) {
    std::fprintf(stderr, "yardsim trace: cannot read '%s'\n", a.file.c_str());
    return kInvalidInput;
  }
  std::string line;
  std::size_t lineNo = 0, shown = 0;
  std::printf("%14s %8s  %-32s %-5s %-14s %s\n", "t[s]", "seq", "model", "kind", "port", "value");
  while (std::getline(in, line)) {
    ++lineNo;
    if (line.empty()) continue;
    YAML::Node r;
    try {
      r = YAML::Load(line);
    } catch (const YAML::Exception& e) {
      std::fprintf(stderr, "%s:%zu: not a JSON object: %s\n", a.file.c_str(), lineNo, e.what());
      return kInvalidInput;
    }
    // (record) => t a number, model, kind and port (if any) text, else the line is named
    double t = 0.0;
    std::string model, port;
    const bool scalars = r.IsMap() && r["t"] && r["model"] && r["kind"] && r["t"].IsScalar() &&
                         r["model"].IsScalar() && r["kind"].IsScalar() &&
                         (!r["port"] || r["port"].IsScalar());
    if (!scalars || !YAML::convert<double>::decode(r["t"], t)) {
      std::fprintf(stderr, "%s:%zu: not a yardsim trace record (needs t a number, model, kind)\n",
                   a.file.c_str(), lineNo);
      return kInvalidInput;
    }
    model = r["model"].Scalar();
    if (r["port"]) port = r["port"].Scalar();
    if (t < a.from || t > a.to) continue;
    if (!models::globMatch(a.model, model)) continue;
    if (a.port != "*" && !models::globMatch(a.port, port)) continue;
    std::string value;
    if (r["value"]) {
      YAML::Emitter e;
      e.SetMapFormat(YAML::Flow);
      e.SetSeqFormat(YAML::Flow);
      e << r["value"];
      value = e.c_str();
    }
    std::printf("%14.6f %8s  %-32s %-5s %-14s %s\n", t,
                r["seq"] ? r["seq"].Scalar().c_str() : "", model.c_str(),
                r["kind"].Scalar().c_str(), port.c_str(), value.c_str());
    ++shown;
  }
  std::fprintf(stderr, "%zu of %zu records shown\n", shown, lineNo);
  return kOk;
}

}  // namespace yardsim::cli
