#include "forces/hydro/impulse_response_cache.hpp"

#include <bit>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

namespace yardsim::forces::hydro {

static_assert(std::endian::native == std::endian::little, "the cache format is little-endian");

namespace {
constexpr char kMagic[8] = {'Y', 'S', 'I', 'M', 'I', 'R', '1', '\n'};
constexpr std::uint32_t kVersion = kImpulseResponseFormat;
constexpr std::uint64_t kMaxCount = 1ull << 26;  // no response has more samples: a damaged count

// (values) => appended as their bytes
struct Writer {
  std::vector<char> bytes;
  template <class T>
  void put(const T& v) {
    const char* p = reinterpret_cast<const char*>(&v);
    bytes.insert(bytes.end(), p, p + sizeof(T));
  }
  template <class M>
  void matrix(const M& m) {
    for (Eigen::Index i = 0; i < m.rows(); ++i)
      for (Eigen::Index j = 0; j < m.cols(); ++j) put(m(i, j));
  }
};

// (bytes, file) => values read in order; a read past the end throws "truncated"
struct Reader {
  const std::vector<char>& bytes;
  std::string file;
  std::size_t at = 0;
  template <class T>
  T get() {
    if (bytes.size() < 8 || bytes.size() - 8 < at + sizeof(T))
      throw CacheError(
          file + ": truncated (ends inside the data); delete it to compute the response again");
    T v;
    std::memcpy(&v, bytes.data() + at, sizeof(T));
    at += sizeof(T);
    return v;
  }
  std::uint64_t count(const char* what) {
    const auto n = get<std::uint64_t>();
    if (n > kMaxCount)
      throw CacheError(file + ": damaged (" + what + " count " + std::to_string(n) + ")");
    return n;
  }
  template <class M>
  void matrix(M& m) {
    for (Eigen::Index i = 0; i < m.rows(); ++i)
      for (Eigen::Index j = 0; j < m.cols(); ++j) m(i, j) = get<double>();
  }
};
}  // namespace

std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t hash) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= p[i];
    hash *= 1099511628211ull;
  }
  return hash;
}

std::filesystem::path impulseResponseCacheDir() {
  if (const char* d = std::getenv("YARDSIM_CACHE_DIR"); d && *d) return d;
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x)
    return std::filesystem::path(x) / "yardsim" / "impulse_responses";
  if (const char* h = std::getenv("HOME"); h && *h)
    return std::filesystem::path(h) / ".cache" / "yardsim" / "impulse_responses";
  return std::filesystem::path(".yardsim_cache") / "impulse_responses";
}

std::filesystem::path cacheFile(const std::filesystem::path& dir, const std::string& key) {
  bool ok = !key.empty() && key.size() <= 200 && key.front() != '.';
  for (char c : key)
    ok = ok && ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                c == '-' || c == '_' || c == '.');
  if (!ok)
    throw std::invalid_argument("impulse-response key '" + key +
                                "': expected letters, digits, '-', '_' and '.'");
  return dir / (key + ".ysir");
}

void writeImpulseResponse(const ImpulseResponse& ir, const std::filesystem::path& file) {
  Writer w;
  w.bytes.insert(w.bytes.end(), std::begin(kMagic), std::end(kMagic));
  w.put(kVersion);
  w.put(static_cast<std::uint32_t>(ir.key.size()));
  w.bytes.insert(w.bytes.end(), ir.key.begin(), ir.key.end());
  w.put(ir.dt);
  w.matrix(ir.aInf);
  w.put(static_cast<std::uint64_t>(ir.radiation.size()));
  for (const auto& K : ir.radiation) w.matrix(K);
  w.put(static_cast<std::uint64_t>(ir.headings.size()));
  for (double b : ir.headings) w.put(b);
  w.put(ir.excitationStart);
  w.put(ir.excitationWindow);
  w.put(static_cast<std::uint32_t>(ir.froudeKrylov ? 1 : 0));
  if (ir.excitation.size() != ir.headings.size())
    throw CacheError(file.string() + ": not written: " + std::to_string(ir.headings.size()) +
                     " headings but " + std::to_string(ir.excitation.size()) +
                     " excitation responses");
  for (const auto& h : ir.excitation) {
    w.put(static_cast<std::uint64_t>(h.size()));
    for (const auto& x : h) w.matrix(x);
  }
  w.put(fnv1a(w.bytes.data(), w.bytes.size()));
  // (a temporary beside it, renamed) => a reader never sees half a file
  std::error_code ec;
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ec);
  const std::filesystem::path tmp = file.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out.write(w.bytes.data(), static_cast<std::streamsize>(w.bytes.size()));
    if (!out)
      throw CacheError(file.string() + ": cannot be written (" +
                       (ec ? ec.message() : "write failed") + ")");
  }
  std::filesystem::rename(tmp, file, ec);
  if (ec) throw CacheError(file.string() + ": cannot be written (" + ec.message() + ")");
}

ImpulseResponse readImpulseResponse(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw CacheError(file.string() + ": cannot be read");
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                std::istreambuf_iterator<char>());
  const std::string f = file.string();
  if (bytes.size() < 8 + 8 + 8 || std::memcmp(bytes.data(), kMagic, 8) != 0)
    throw CacheError(f + ": not an impulse-response file (no YSIMIR1 header)");
  std::uint64_t stored;
  std::memcpy(&stored, bytes.data() + bytes.size() - 8, 8);
  if (fnv1a(bytes.data(), bytes.size() - 8) != stored)
    throw CacheError(f + ": damaged (checksum mismatch); delete it to compute the response again");
  Reader r{bytes, f, 8};
  if (const auto v = r.get<std::uint32_t>(); v != kVersion)
    throw CacheError(f + ": format version " + std::to_string(v) + ", this build reads version " +
                     std::to_string(kVersion));
  ImpulseResponse ir;
  const auto keySize = r.get<std::uint32_t>();
  if (keySize > 1000 || r.at + keySize > bytes.size() - 8)
    throw CacheError(f + ": damaged (key length)");
  ir.key.assign(bytes.data() + r.at, keySize);
  r.at += keySize;
  ir.dt = r.get<double>();
  r.matrix(ir.aInf);
  ir.radiation.resize(r.count("radiation"));
  for (auto& K : ir.radiation) r.matrix(K);
  ir.headings.resize(r.count("heading"));
  for (double& b : ir.headings) b = r.get<double>();
  ir.excitationStart = r.get<double>();
  ir.excitationWindow = r.get<double>();
  const auto fk = r.get<std::uint32_t>();
  if (fk > 1) throw CacheError(f + ": damaged (Froude-Krylov flag " + std::to_string(fk) + ")");
  ir.froudeKrylov = fk == 1;
  ir.excitation.resize(ir.headings.size());
  for (auto& h : ir.excitation) {
    h.resize(r.count("excitation"));
    for (auto& x : h) r.matrix(x);
  }
  if (r.at != bytes.size() - 8)
    throw CacheError(f + ": damaged (" + std::to_string(bytes.size() - 8 - r.at) +
                     " bytes left over)");
  return ir;
}

std::optional<ImpulseResponse> loadCachedResponse(const std::filesystem::path& dir,
                                                  const std::string& key) {
  const std::filesystem::path file = cacheFile(dir, key);
  if (!std::filesystem::exists(file)) return std::nullopt;
  ImpulseResponse ir = readImpulseResponse(file);
  if (ir.key != key)
    throw CacheError(file.string() + ": holds the response of key '" + ir.key + "', not '" + key +
                     "'");
  return ir;
}

}  // namespace yardsim::forces::hydro
