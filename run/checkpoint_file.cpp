#include "run/checkpoint_file.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "devs/checkpoint_archive.hpp"
#include "run/timeseries_writer.hpp"
#include "scene/resolved_listing.hpp"
#include "scene/sha256.hpp"

namespace yardsim::run {

using devs::CheckpointError;

std::string sceneFingerprint(const scene::Scene& scene) {
  return scene::sha256Hex(scene.sha256 + "\n" + scene::resolvedListing(scene));
}

std::string checkpointName(double t) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "t%010.3f.ckpt", t);
  return buf;
}

void writeCheckpointFile(const std::filesystem::path& file, const std::string& fingerprint,
                         double t, const std::string& payload) {
  // (header lines, payload) => a temporary file, renamed over the target when complete
  char time[64];
  std::snprintf(time, sizeof time, "%.17g", t);
  std::ostringstream header;
  header << "YARDSIM-CHECKPOINT " << kCheckpointFormat << "\n"
         << "yardsim " << kVersion << "\n"
         << "scene_sha256 " << fingerprint << "\n"
         << "time " << time << "\n"
         << "payload_bytes " << payload.size() << "\n"
         << "payload_sha256 " << scene::sha256Hex(payload) << "\n\n";
  std::filesystem::create_directories(file.parent_path());
  const std::filesystem::path tmp = file.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << header.str();
    out.write(payload.data(), static_cast<std::streamsize>(payload.size()));
    if (!out.flush()) throw std::runtime_error("cannot write the checkpoint " + tmp.string());
  }
  std::filesystem::rename(tmp, file);
}

namespace {
// (stream, key) => the value of the header line "key value", else CheckpointError
std::string headerLine(std::istream& in, const std::filesystem::path& file,
                       const std::string& key) {
  std::string line;
  if (!std::getline(in, line) || line.rfind(key + " ", 0) != 0)
    throw CheckpointError(file.string() + ": not a yardsim checkpoint, or a truncated one (no '" +
                          key + "' line in its header)");
  return line.substr(key.size() + 1);
}
}  // namespace

CheckpointFile readCheckpointFile(const std::filesystem::path& file,
                                  const std::string& fingerprint) {
  // (path) => a regular file (a device such as /dev/zero has a header line without end)
  std::error_code ec;
  if (std::filesystem::exists(file, ec) && !std::filesystem::is_regular_file(file, ec))
    throw CheckpointError(file.string() + ": not a regular file, so not a checkpoint");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw CheckpointError(file.string() + ": cannot open the checkpoint");
  // (header) => format, version and scene checked before the payload is read
  const std::string format = headerLine(in, file, "YARDSIM-CHECKPOINT");
  if (format != std::to_string(kCheckpointFormat))
    throw CheckpointError(file.string() + ": checkpoint format " + format +
                          ", this yardsim reads " + std::to_string(kCheckpointFormat));
  const std::string version = headerLine(in, file, "yardsim");
  if (version != kVersion)
    throw CheckpointError(file.string() + ": written by yardsim " + version + ", this is yardsim " +
                          kVersion + "; a checkpoint restarts only the version that wrote it");
  if (headerLine(in, file, "scene_sha256") != fingerprint)
    throw CheckpointError(file.string() +
                          ": written for another scene (its fingerprint differs: another file, "
                          "include or parameter); restart with the scene that wrote it");
  CheckpointFile out;
  const std::string time = headerLine(in, file, "time");
  char* end = nullptr;
  out.t = std::strtod(time.c_str(), &end);
  if (end == time.c_str() || !std::isfinite(out.t))
    throw CheckpointError(file.string() + ": the header's time '" + time + "' is not a number");
  const std::string bytes = headerLine(in, file, "payload_bytes");
  const std::string digest = headerLine(in, file, "payload_sha256");
  std::string blank;
  if (!std::getline(in, blank) || !blank.empty())
    throw CheckpointError(file.string() + ": no empty line after the checkpoint's header");
  // (payload) => exactly as many bytes as announced, with the announced SHA-256
  const unsigned long long n = std::strtoull(bytes.c_str(), nullptr, 10);
  out.payload.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (out.payload.size() != n)
    throw CheckpointError(file.string() + ": the checkpoint holds " +
                          std::to_string(out.payload.size()) +
                          " bytes of state where its header "
                          "announces " +
                          bytes + " (a truncated file?)");
  if (scene::sha256Hex(out.payload) != digest)
    throw CheckpointError(file.string() +
                          ": the checkpoint's state does not match its SHA-256 "
                          "(an altered or damaged file)");
  return out;
}

}  // namespace yardsim::run
