#include "devs/buffered_file.hpp"

#include <system_error>

namespace yardsim::devs {

// (path, mode) => the buffer handed to the file's stream before it opens (libstdc++ takes a
// buffer only then), then the file opened; a file to be truncated is removed first, so the new
// one is a fresh file: on ext4 (auto_da_alloc) a file truncated and written again is flushed to
// disk at its close, in the writer's time (a rerun into the same folder paid 4 ms of the double
// pendulum's 55 ms for it). If the removal fails, the open truncates as before.
BufferedFile::BufferedFile(const std::filesystem::path& path, std::ios::openmode mode)
    : buffer_(std::make_unique_for_overwrite<char[]>(kBufferBytes)) {
  out_.rdbuf()->pubsetbuf(buffer_.get(), static_cast<std::streamsize>(kBufferBytes));
  if ((mode & std::ios::trunc) && !(mode & std::ios::app)) {
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
  }
  out_.open(path, mode);
}

}  // namespace yardsim::devs
