#include <cstdio>
#include <stdexcept>

#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "cli/scene_input.hpp"
#include "scene/assembler.hpp"
#include "models/channels.hpp"
#include "models/registry.hpp"

namespace yardsim::cli {

int listTypesCommand() {
  const auto& reg = models::Registry::instance();
  for (const auto& name : reg.names()) {
    const models::TypeInfo& t = *reg.find(name);
    std::printf("%s\n  %s\n", t.name.c_str(), t.summary.c_str());
    for (const auto& p : t.params) {
      std::printf("  param %-14s %s%s%s%s\n", p.name.c_str(), models::describe(p.kind).c_str(),
                  p.unit.empty() ? "" : (" [" + p.unit + "]").c_str(),
                  p.required ? ", required" : (", default " + p.defaultValue).c_str(),
                  p.doc.empty() ? "" : (" — " + p.doc).c_str());
    }
    models::Params defaults;
    for (const auto& p : t.params)
      if (!p.required) defaults.set(p.name, YAML::Load(p.defaultValue), {});
    try {
      for (const auto& port : t.ports(defaults))
        std::printf("  %-5s %-14s %s\n", port.input ? "in" : "out", port.name.c_str(),
                    port.type.c_str());
    } catch (const std::out_of_range&) {
      std::printf("  (ports depend on the parameters)\n");
    }
  }
  return kOk;
}

int listChannelsCommand(const std::string& file) {
  auto scene = loadAndReport(file);
  if (!scene) return kInvalidInput;
  auto root = scene::assemble(*scene);
  for (const auto& c : models::collectChannels(*root)) std::printf("%s\n", c.column().c_str());
  return kOk;
}

}  // namespace yardsim::cli
