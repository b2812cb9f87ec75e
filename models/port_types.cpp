#include "models/port_types.hpp"

#include "devs/type_name.hpp"
#include "models/multibody/messages.hpp"

namespace yardsim::models {
namespace {

template <class T>
PortType make(const char* name) {
  return {name, &typeid(T),
          [](devs::Model& m, std::string n) -> devs::PortBase& { return m.addInPort<T>(std::move(n)); },
          [](devs::Model& m, std::string n) -> devs::PortBase& {
            return m.addOutPort<T>(std::move(n));
          }};
}

const std::vector<PortType>& table() {
  static const std::vector<PortType> types{
      make<int>("int"),           make<double>("double"),
      make<bool>("bool"),         make<std::string>("string"),
      make<SetPoint>("setpoint"), make<MechanicsEvent>("mechanics_event")};
  return types;
}

}  // namespace

const PortType* findPortType(std::string_view name) {
  for (const auto& t : table())
    if (t.name == name) return &t;
  return nullptr;
}

std::string portTypeName(const std::type_info& type) {
  for (const auto& t : table())
    if (*t.type == type) return t.name;
  return devs::typeName(type);
}

std::vector<std::string> portTypeNames() {
  std::vector<std::string> out;
  for (const auto& t : table()) out.push_back(t.name);
  return out;
}

}  // namespace yardsim::models
