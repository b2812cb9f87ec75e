#pragma once
// Value types a scene may name for the ports of a coupled model (inputs: {in: int}), mapped to
// the C++ types of the atomic ports they connect to.
#include <string>
#include <string_view>
#include <typeinfo>
#include <vector>

#include "devs/coupled.hpp"

namespace yardsim::models {

struct PortType {
  std::string name;
  const std::type_info* type;
  devs::PortBase& (*addInput)(devs::Model&, std::string);
  devs::PortBase& (*addOutput)(devs::Model&, std::string);
};

// (name) => the port type, or nullptr; built in: int, double, bool, string, setpoint,
// mechanics_event
const PortType* findPortType(std::string_view name);
// (C++ type) => its scene name, or the demangled C++ name when it has none
std::string portTypeName(const std::type_info& type);
std::vector<std::string> portTypeNames();

}  // namespace yardsim::models
