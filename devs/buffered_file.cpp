#include "devs/buffered_file.hpp"

namespace yardsim::devs {

// (path, mode) => the buffer handed to the file's stream before it opens (libstdc++ takes a
// buffer only then), then the file opened
BufferedFile::BufferedFile(const std::filesystem::path& path, std::ios::openmode mode)
    : buffer_(std::make_unique_for_overwrite<char[]>(kBufferBytes)) {
  out_.rdbuf()->pubsetbuf(buffer_.get(), static_cast<std::streamsize>(kBufferBytes));
  out_.open(path, mode);
}

}  // namespace yardsim::devs
