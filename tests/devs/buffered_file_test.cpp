// BufferedFile (devs/buffered_file.hpp): what goes through its buffer reaches the file whole and in
// order, in pieces smaller and larger than the buffer, and a file it cannot open is reported.
#include "devs/buffered_file.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "support/split_mix.hpp"

using yardsim::devs::BufferedFile;

TEST_CASE("a BufferedFile writes every byte in order, through and past its buffer") {
  const auto dir = std::filesystem::temp_directory_path() / "yardsim_buffered_file_test";
  std::filesystem::create_directories(dir);
  const auto path = dir / "out.txt";
  {
    std::ofstream old(path);
    old << "an older, longer file that the new one replaces whole";
  }
  // (pieces of 1 byte to 1.5 buffers, random letters) => the expected text, written as it grows
  std::string expected;
  yardsim::test::SplitMix64 next{0x243f6a8885a308d3ULL};
  {
    BufferedFile file(path);
    REQUIRE(file.stream());
    while (expected.size() < 3 * BufferedFile::kBufferBytes + 12345) {
      const std::size_t n =
          next() % 3 == 0 ? next() % (BufferedFile::kBufferBytes * 3 / 2) + 1 : next() % 300 + 1;
      std::string piece(n, ' ');
      for (char& c : piece) c = static_cast<char>('a' + next() % 26);
      if (next() % 2 == 0)
        file.stream() << piece;
      else
        file.stream().rdbuf()->sputn(piece.data(), static_cast<std::streamsize>(piece.size()));
      expected += piece;
    }
    REQUIRE(file.stream());
  }  // closed: the rest of the buffer written
  std::ifstream in(path, std::ios::binary);
  const std::string got{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  CHECK(got.size() == expected.size());
  CHECK(got == expected);
  std::filesystem::remove_all(dir);
}

TEST_CASE("a BufferedFile that cannot be opened tests false") {
  BufferedFile missing(std::filesystem::temp_directory_path() / "no_such_dir_yardsim" / "x.txt");
  CHECK_FALSE(missing.stream());
}

TEST_CASE("a BufferedFile replaces an existing file with a new one rather than truncating it") {
  // (a file with a second name, a hard link) => the new text under the path, the old text kept
  // under the link: the old file was removed, not truncated and written again (which ext4
  // flushes to disk at its close)
  const auto dir = std::filesystem::temp_directory_path() / "yardsim_buffered_file_replace_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto path = dir / "trace.jsonl", link = dir / "earlier.jsonl";
  std::ofstream(path) << "the earlier run's trace";
  std::filesystem::create_hard_link(path, link);
  {
    BufferedFile file(path);
    REQUIRE(file.stream());
    file.stream() << "this run's trace";
  }
  auto text = [](const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  };
  CHECK(text(path) == "this run's trace");
  CHECK(text(link) == "the earlier run's trace");
  CHECK(std::filesystem::hard_link_count(path) == 1);
  // (append mode) => the file kept and written on
  {
    BufferedFile file(path, std::ios::out | std::ios::app);
    file.stream() << ", continued";
  }
  CHECK(text(path) == "this run's trace, continued");
  std::filesystem::remove_all(dir);
}
