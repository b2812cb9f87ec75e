#pragma once
// The disk cache of impulse responses (docs/hydrodynamics.md, "The cache"): one file per key
// (ImpulseResponse::key, a hash of the hull mesh and the settings that made it), named
// `<key>.ysir` in the cache folder. Format, version 3, every number little-endian:
//   "YSIMIR1\n" (8 bytes), u32 version, u32 key length, the key (UTF-8), f64 dt, 36 f64 aInf
//   (row-major), u64 L then L x 36 f64 radiation (row-major), u64 H then H f64 headings, f64
//   excitationStart, f64 excitationWindow (version 2), u32 froudeKrylov 0 or 1 (version 3), per
//   heading u64 N then N x 6 f64 excitation, then u64 FNV-1a 64 of every byte before it.
// Doubles are stored as their bit patterns: a read gives back every value to the last bit.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

#include "forces/hydro/impulse_response.hpp"

namespace yardsim::forces::hydro {

/// The format version this build writes and reads (part of every cache key: a file of another
/// version is never looked up, only refused when given by name)
inline constexpr std::uint32_t kImpulseResponseFormat = 3;

// A cache file that is not one, is damaged, is of another version or holds another key.
class CacheError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// () => the cache folder: $YARDSIM_CACHE_DIR, else $XDG_CACHE_HOME/yardsim/impulse_responses, else
// $HOME/.cache/yardsim/impulse_responses, else ./.yardsim_cache/impulse_responses
std::filesystem::path impulseResponseCacheDir();
// (folder, key of letters, digits, '-', '_' and '.') => its file; throws std::invalid_argument for
// another key (empty, a path)
std::filesystem::path cacheFile(const std::filesystem::path& dir, const std::string& key);

// (response, file) => written whole (a temporary file renamed over it); throws CacheError when
// the folder cannot be made or the file written
void writeImpulseResponse(const ImpulseResponse& ir, const std::filesystem::path& file);
// (file) => the response; throws CacheError naming the file and what is wrong
ImpulseResponse readImpulseResponse(const std::filesystem::path& file);
// (folder, key) => the cached response, or nothing when there is no file; throws CacheError for
// a damaged file or one that holds another key
std::optional<ImpulseResponse> loadCachedResponse(const std::filesystem::path& dir,
                                                  const std::string& key);

// (bytes) => FNV-1a 64 (also the hash behind the keys), continuing from `hash`
std::uint64_t fnv1a(const void* data, std::size_t size,
                    std::uint64_t hash = 14695981039346656037ull);

}  // namespace yardsim::forces::hydro
