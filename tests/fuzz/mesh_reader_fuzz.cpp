// libFuzzer target: the OBJ and STL readers (tests/fuzz/README.md). (bytes; the first byte picks
// OBJ, ASCII STL or binary STL) => readMesh and readClosedMesh; a bad file is a
// std::runtime_error naming it, anything else escaping (or a crash, leak, hang) is a finding.
#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "forces/geometry/mesh_io.hpp"
#include "fuzz/fuzz_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const char* names[] = {"mesh.obj", "mesh.stl"};
  const std::string name = names[data[0] % 2];
  const auto dir = yardsim::fuzz::writeFiles(
      {{name, std::string(reinterpret_cast<const char*>(data + 1), size - 1)}});
  const std::string path = (dir / name).string();
  for (auto* read : {&yardsim::forces::readMesh, &yardsim::forces::readClosedMesh}) {
    try {
      (void)read(path);
    } catch (const std::runtime_error&) {
      // a refused mesh: what the readers promise
    }
  }
  return 0;
}
