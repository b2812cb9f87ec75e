#pragma once
// An output file with a write buffer of its own, larger than the standard library's (8 KiB in
// libstdc++): a trace or a time series of some megabytes goes to the kernel in a few dozen
// writes instead of a thousand or more. The bytes written are the same.
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <memory>

namespace yardsim::devs {

class BufferedFile {
 public:
  // Bytes buffered before a write to the file.
  static constexpr std::size_t kBufferBytes = std::size_t{1} << 18;

  // (path, mode) => the file opened for writing with the buffer set; stream() tests false when
  // it could not be opened (the caller reports it)
  explicit BufferedFile(const std::filesystem::path& path,
                        std::ios::openmode mode = std::ios::out | std::ios::trunc);
  BufferedFile(const BufferedFile&) = delete;
  BufferedFile& operator=(const BufferedFile&) = delete;
  std::ofstream& stream() { return out_; }

 private:
  std::unique_ptr<char[]> buffer_;  // before out_: the stream flushes into the file through it
  std::ofstream out_;
};

}  // namespace yardsim::devs
