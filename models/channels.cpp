#include "models/channels.hpp"

#include <fnmatch.h>

namespace yardsim::models {

bool globMatch(const std::string& glob, const std::string& text) {
  return fnmatch(glob.c_str(), text.c_str(), 0) == 0;
}

std::vector<Channel> collectChannels(const devs::Model& root) {
  std::vector<Channel> out;
  std::vector<const devs::Model*> stack{&root};
  while (!stack.empty()) {
    const devs::Model* m = stack.back();
    stack.pop_back();
    if (!m->isAtomic()) {
      const auto& kids = static_cast<const devs::Coupled*>(m)->components();
      for (auto it = kids.rbegin(); it != kids.rend(); ++it) stack.push_back(it->get());
      continue;
    }
    if (const auto* obs = dynamic_cast<const Observable*>(m)) {
      const std::size_t first = out.size();
      obs->channels(out);
      if (!obs->channelNamesArePaths())
        for (std::size_t i = first; i < out.size(); ++i) out[i].name = m->path() + "." + out[i].name;
    }
  }
  return out;
}

std::vector<Channel> selectChannels(const std::vector<Channel>& all,
                                    const std::vector<std::string>& globs) {
  std::vector<Channel> out;
  for (const auto& c : all)
    for (const auto& g : globs)
      if (globMatch(g, c.name)) {
        out.push_back(c);
        break;
      }
  return out;
}

}  // namespace yardsim::models
