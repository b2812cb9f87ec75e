#include "scene/provider_readers.hpp"

#include <algorithm>
#include <stdexcept>

namespace yardsim::scene {

namespace {

const std::vector<std::string> kBuiltInKeys{
    "bodies",     "ropes",           "equalizers",       "loops",
    "loads",      "watch",           "gravity",          "water",
    "wind",       "hydrostatics",    "wind_loads",       "current_loads",
    "damping",    "drive_bandwidth", "drive_max_effort", "drive_tolerance",
    "equilibrium", "hydrodynamics"};

std::vector<ProviderReader>& readers() {
  static std::vector<ProviderReader> all;
  return all;
}

}  // namespace

bool registerProviderReader(ProviderReader reader) {
  const bool taken =
      std::find(kBuiltInKeys.begin(), kBuiltInKeys.end(), reader.key) != kBuiltInKeys.end() ||
      std::any_of(readers().begin(), readers().end(),
                  [&](const auto& r) { return r.key == reader.key; });
  if (taken)
    throw std::invalid_argument("provider reader: the mechanics key '" + reader.key + "' is taken");
  readers().push_back(std::move(reader));
  return true;
}

const std::vector<ProviderReader>& providerReaders() {
  return readers();
}

std::vector<std::string> mechanicsKeys() {
  std::vector<std::string> keys = kBuiltInKeys;
  for (const auto& r : readers()) keys.push_back(r.key);
  return keys;
}

mechanics::MechanicsSpec::Point readPoint(const spec::Reader& r, const YAML::Node& n,
                                          const std::string& key) {
  mechanics::MechanicsSpec::Point out{"world", dynamics::Vector3::Zero()};
  if (!r.keys(n, {"body", "point"}, key)) return out;
  if (const YAML::Node b = n["body"]) {
    if (b.IsScalar())
      out.first = b.Scalar();
    else
      r.fail(b, key + ".body", "expected a body name");
  }
  out.second = r.length3(n["point"], key + ".point", dynamics::Vector3::Zero());
  return out;
}

}  // namespace yardsim::scene
