#pragma once
// Force providers contributed by reader functions (docs/extending.md): a reader registers the
// `mechanics:` key it reads (springs, mooring, ...) and turns one named entry into a
// MechanicsSpec::ProviderSpec (the attachment points, and a function that builds the
// forces::ForceProvider for the system's model). The mechanics reader, the key checks, the
// merging of fragments into mechanical systems and the run then treat it like any built-in
// provider: one list, counted by the energy balance and the stiffness estimate, with the
// channels <name>.energy [J] and <name>.power [W]. Problems are reported at their YAML nodes.
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "mechanics/description.hpp"
#include "scene/spec_reader.hpp"

namespace yardsim::scene {

// A problem a provider finds only when it is built from its whole system (a pattern that matches
// nothing, a shape the kernel refuses), at a node of its entry: line and column (1-based) in the
// file of the fragment that declared it, the key path below `mechanics.<kind>` (or from the
// scene root when `rootKey`), and the provider's full name.
struct ProviderPlaceError : std::invalid_argument {
  ProviderPlaceError(const std::string& message, std::string provider_, int line_, int column_,
                     std::string key_, bool rootKey_ = false)
      : std::invalid_argument(message),
        provider(std::move(provider_)),
        line(line_),
        column(column_),
        key(std::move(key_)),
        rootKey(rootKey_) {}
  std::string provider;
  int line = 0, column = 0;
  std::string key;
  bool rootKey = false;
};

// (entry name, its node, the reader that reports problems at their nodes with key paths below
// the block, the entry's key path) => the provider's spec (kind and name are filled in after)
using ProviderRead = std::function<mechanics::MechanicsSpec::ProviderSpec(
    const std::string& name, const YAML::Node& node, const spec::Reader& r,
    const std::string& key)>;

struct ProviderReader {
  std::string key;      // the mechanics key: `springs:` => {name: {...}, ...}
  std::string summary;  // one line for `yardsim list-types` and error messages
  ProviderRead read;
};

// (reader) => registered; true (for YARDSIM_REGISTER_PROVIDER); a second reader for a key or a
// built-in key is refused with std::invalid_argument
bool registerProviderReader(ProviderReader reader);
const std::vector<ProviderReader>& providerReaders();

// the keys of a `mechanics:` block: the built-in ones, then every registered reader's
std::vector<std::string> mechanicsKeys();

// ({body, point: [x, y, z]} at key) => the attachment (body "world" when not given); the body
// name is checked when the fragments are merged
mechanics::MechanicsSpec::Point readPoint(const spec::Reader& r, const YAML::Node& n,
                                          const std::string& key);

}  // namespace yardsim::scene

// YARDSIM_REGISTER_PROVIDER(id, ProviderReader{...}) in a .cpp of scene/providers/ (or of your own
// executable) registers a reader before main().
#define YARDSIM_REGISTER_PROVIDER(id, ...)                          \
  [[maybe_unused]] static const bool yardsim_provider_reader_##id = \
      ::yardsim::scene::registerProviderReader(__VA_ARGS__)
