#pragma once
// Checkpoint files (docs/scenes.md, checkpoints): OUT/checkpoints/t000050.000.ckpt. A text
// header that `head` shows, then the payload (devs/checkpoint_archive.hpp, a tagged binary):
//   YARDSIM-CHECKPOINT 1          the file format and its version
//   yardsim 0.1.0                 the yardsim that wrote it (another one is refused)
//   scene_sha256 <64 hex>         the scene's fingerprint: the root file and everything it
//                                 resolves to (includes, parameters); another scene is refused
//   time 50                       the simulated time it was taken at, s
//   payload_bytes <n>             the payload's length and SHA-256: a truncated or altered
//   payload_sha256 <64 hex>       file is refused
//   (one empty line, then the payload)
#include <filesystem>
#include <string>

#include "scene/scene.hpp"

namespace yardsim::run {

inline constexpr int kCheckpointFormat = 2;  // 2: alarms carry their message and worst time

// (scene) => SHA-256 over its root file's SHA-256 and its resolved listing (what would run)
std::string sceneFingerprint(const scene::Scene& scene);

// (t) => "t000050.000.ckpt": the time in s with three decimals, six digits before the point
std::string checkpointName(double t);

// (file, scene fingerprint, time, payload) => the file, written whole or not at all (a
// temporary beside it is renamed); throws std::runtime_error naming the file when it cannot be
void writeCheckpointFile(const std::filesystem::path& file, const std::string& fingerprint,
                         double t, const std::string& payload);

struct CheckpointFile {
  double t = 0.0;       // s
  std::string payload;  // the archive, verified against its length and SHA-256
};
// (file, the fingerprint of the scene it is to be applied to) => its time and payload; throws
// devs::CheckpointError saying why not (missing, not a checkpoint, another format or yardsim
// version, another scene, truncated or altered)
CheckpointFile readCheckpointFile(const std::filesystem::path& file,
                                  const std::string& fingerprint);

}  // namespace yardsim::run
