#pragma once
// A multibody model's channels read by name in example tests: the channels' current values.
#include <map>
#include <string>
#include <vector>

#include "models/channels.hpp"
#include "models/multibody/multibody_model.hpp"

namespace yardsim::testing {

// (model) => the channels' current values, by name
struct ChannelReader {
  std::map<std::string, models::Channel> byName;
  explicit ChannelReader(const models::MultibodyModel& mb) {
    std::vector<models::Channel> all;
    mb.channels(all);
    for (auto& c : all) byName.emplace(c.name, c);
  }
  double operator()(const std::string& name) const { return byName.at(name).read(); }
};

}  // namespace yardsim::testing
