#pragma once
// Human-readable C++ type names for error messages (demangled typeid names).
#include <string>
#include <typeinfo>

namespace yardsim::devs {

// (type_info) => demangled name, e.g. "double" or "std::vector<int, ...>"
std::string typeName(const std::type_info& type);

}  // namespace yardsim::devs
