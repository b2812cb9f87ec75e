#include "devs/checkpoint_archive.hpp"

#include <bit>
#include <cstring>

namespace yardsim::devs {
namespace {
constexpr char kF64 = 'd', kI64 = 'i', kBool = 'b', kStr = 's', kList = 'l', kSection = 'S';

// (tag) => its name in messages
std::string_view tagName(char tag) {
  switch (tag) {
    case kF64:
      return "a number";
    case kI64:
      return "an integer";
    case kBool:
      return "a boolean";
    case kStr:
      return "a string";
    case kList:
      return "a list";
    case kSection:
      return "a section";
    default:
      return "an unknown tag";
  }
}

static_assert(std::endian::native == std::endian::little,
              "checkpoints are written little-endian; a big-endian port must swap bytes here");
}  // namespace

void CheckpointWriter::f64(double v) {
  bytes_ += kF64;
  raw(&v, sizeof v);
}
void CheckpointWriter::i64(std::int64_t v) {
  bytes_ += kI64;
  raw(&v, sizeof v);
}
void CheckpointWriter::boolean(bool v) {
  bytes_ += kBool;
  bytes_ += v ? '\1' : '\0';
}
void CheckpointWriter::str(std::string_view v) {
  bytes_ += kStr;
  const auto n = static_cast<std::uint64_t>(v.size());
  raw(&n, sizeof n);
  bytes_.append(v);
}
void CheckpointWriter::list(std::size_t n) {
  bytes_ += kList;
  const auto m = static_cast<std::uint64_t>(n);
  raw(&m, sizeof m);
}
void CheckpointWriter::section(std::string_view name) {
  bytes_ += kSection;
  const auto n = static_cast<std::uint64_t>(name.size());
  raw(&n, sizeof n);
  bytes_.append(name);
}

void CheckpointReader::expect(char tag, std::string_view what) {
  if (pos_ >= bytes_.size())
    throw CheckpointError("the checkpoint ends at byte " + std::to_string(pos_) + " where " +
                          std::string(what) + " was expected (a truncated file?)");
  if (bytes_[pos_] != tag)
    throw CheckpointError("byte " + std::to_string(pos_) + " of the checkpoint holds " +
                          std::string(tagName(bytes_[pos_])) + " where " + std::string(what) +
                          " was expected (written by another yardsim?)");
  ++pos_;
}

void CheckpointReader::raw(void* p, std::size_t n, std::string_view what) {
  if (bytes_.size() - pos_ < n)
    throw CheckpointError("the checkpoint ends inside " + std::string(what) + " at byte " +
                          std::to_string(pos_) + " (a truncated file?)");
  std::memcpy(p, bytes_.data() + pos_, n);
  pos_ += n;
}

double CheckpointReader::f64() {
  expect(kF64, tagName(kF64));
  double v;
  raw(&v, sizeof v, tagName(kF64));
  return v;
}
std::int64_t CheckpointReader::i64() {
  expect(kI64, tagName(kI64));
  std::int64_t v;
  raw(&v, sizeof v, tagName(kI64));
  return v;
}
bool CheckpointReader::boolean() {
  expect(kBool, tagName(kBool));
  char c;
  raw(&c, 1, tagName(kBool));
  return c != 0;
}
std::string CheckpointReader::str() {
  expect(kStr, tagName(kStr));
  std::uint64_t n;
  raw(&n, sizeof n, tagName(kStr));
  if (n > bytes_.size() - pos_)
    throw CheckpointError("the checkpoint ends inside a string at byte " + std::to_string(pos_) +
                          " (a truncated file?)");
  std::string v(bytes_.substr(pos_, n));
  pos_ += n;
  return v;
}
std::size_t CheckpointReader::list() {
  expect(kList, tagName(kList));
  std::uint64_t n;
  raw(&n, sizeof n, tagName(kList));
  // (length) => each element takes at least its tag byte: a longer list cannot be in the file
  if (n > bytes_.size() - pos_)
    throw CheckpointError("a list of " + std::to_string(n) + " values at byte " +
                          std::to_string(pos_) + " is longer than the checkpoint");
  return n;
}
void CheckpointReader::section(std::string_view name) {
  const std::string what = "the section '" + std::string(name) + "'";
  expect(kSection, what);
  std::uint64_t n;
  raw(&n, sizeof n, what);
  if (n > bytes_.size() - pos_ || bytes_.substr(pos_, n) != name)
    throw CheckpointError("the checkpoint holds another section at byte " + std::to_string(pos_) +
                          " where " + what + " was expected (another scene or yardsim version?)");
  pos_ += n;
}

}  // namespace yardsim::devs
