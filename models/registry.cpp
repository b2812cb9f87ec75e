#include "models/registry.hpp"

#include <stdexcept>

namespace yardsim::models {

Registry& Registry::instance() {
  static Registry registry;
  return registry;
}

void Registry::add(TypeInfo info) {
  if (info.name.empty() || !info.create || !info.ports)
    throw std::logic_error("model type '" + info.name + "' needs a name, ports and a factory");
  const std::string name = info.name;
  if (!types_.emplace(name, std::move(info)).second)
    throw std::logic_error("model type '" + name + "' is registered twice");
}

const TypeInfo* Registry::find(std::string_view name) const {
  auto it = types_.find(name);
  return it == types_.end() ? nullptr : &it->second;
}

std::vector<std::string> Registry::names() const {
  std::vector<std::string> out;
  for (const auto& [name, _] : types_) out.push_back(name);
  return out;
}

std::unique_ptr<devs::AtomicBase> Registry::create(const TypeInfo& type, const std::string& name,
                                                   const Params& params) {
  ++made_[type.name];
  return type.create(name, params);
}

std::map<std::string, std::size_t> Registry::instantiated() const { return made_; }

}  // namespace yardsim::models
