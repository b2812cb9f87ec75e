// libFuzzer target: the scene loader with includes, meshes and CSV files (tests/fuzz/README.md).
// (bytes: one or more files, fuzz_files.hpp) => loadScene on the first; it must return a scene or
// diagnostics and never throw, crash, leak or hang.
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_files.hpp"
#include "scene/scene_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto files = yardsim::fuzz::splitFiles(data, size, "scene.yaml");
  const auto dir = yardsim::fuzz::writeFiles(files);
  // an exception escaping here is a finding: the CLI would call it an internal error (exit 3)
  (void)yardsim::scene::loadScene(dir / files.front().first);
  return 0;
}
