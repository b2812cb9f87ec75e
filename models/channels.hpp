#pragma once
// Recorded quantities. A model that has quantities to record implements Observable and lists
// its channels (name relative to the model, unit, and the one function that computes the
// value); every writer (time series, report) reads a channel through that function only.
// A channel's full name is "<model path>.<name>" and its column "<full name>[<unit>]".
#include <functional>
#include <string>
#include <vector>

#include "devs/coupled.hpp"

namespace yardsim::models {

struct Channel {
  std::string name;  // full name once collected, e.g. "crane1.hoist1.tension"
  std::string unit;  // SI unit, "-" for counts and ratios
  std::function<double()> read;
  std::string column() const { return name + "[" + unit + "]"; }
};

class Observable {
 public:
  virtual ~Observable() = default;
  // (out) => this model's channels appended, names relative to the model ("x", "hoist1.tension")
  virtual void channels(std::vector<Channel>& out) const = 0;
  // true when the names are already full paths (a scene's mechanical system names its elements
  // by their paths: crane1.hoist1.tension)
  virtual bool channelNamesArePaths() const { return false; }
};

// (root model) => every channel of every Observable atomic below it, with full names
std::vector<Channel> collectChannels(const devs::Model& root);
// (channels, globs) => those whose full name matches any glob (*, ?, [..]), in order
std::vector<Channel> selectChannels(const std::vector<Channel>& all,
                                    const std::vector<std::string>& globs);
// (text, glob) => whether the glob matches the whole text
bool globMatch(const std::string& glob, const std::string& text);

}  // namespace yardsim::models
