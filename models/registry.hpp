#pragma once
// The model registry: atomic model types register themselves by name, with their parameter
// declarations, their ports and a factory, so the scene assembler has no list of types.
// Built-in types and user types register the same way:
//
//   YARDSIM_REGISTER_TYPE(myType, yardsim::models::TypeInfo{ .name = "my_type", ... });
#include <atomic>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "devs/atomic.hpp"
#include "models/params.hpp"

namespace yardsim::models {

struct PortSpec {
  std::string name;
  std::string type;  // a registered port type name: int, double, bool, string, ...
  bool input = true;
  bool optional = false;  // an input that may stay unconnected without a warning
};

// A mechanical element (joint, rope, body) a model has, or an actor names (in parameter `param`).
struct ElementRef {
  std::string kind;
  std::string name;
  std::string param;
};

struct TypeInfo {
  std::string name;
  std::string summary;
  std::vector<ParamSpec> params;
  // (params) => the ports of an instance
  std::function<std::vector<PortSpec>(const Params&)> ports;
  // (instance name, params) => the atomic model
  std::function<std::unique_ptr<devs::AtomicBase>(const std::string&, const Params&)> create;
  // (params, checker) => errors beyond the declared kinds (ranges, consistency); optional
  std::function<void(const Params&, ParamCheck&)> check;
  // (params) => true when an input can produce an output at the same time (zero delay): such
  // models closing a loop make an algebraic loop. Unset: never.
  std::function<bool(const Params&)> feedthrough;
  // (params) => the mechanical elements an instance has (multibody models); optional
  std::function<std::vector<ElementRef>(const Params&)> elements = {};
  // (params) => the elements an instance acts on through its `setpoint` port (actors); optional
  std::function<std::vector<ElementRef>(const Params&)> references = {};
};

class Registry {
 public:
  static Registry& instance();
  // (type) => registered; throws std::logic_error on a duplicate name
  void add(TypeInfo info);
  const TypeInfo* find(std::string_view name) const;
  std::vector<std::string> names() const;
  // (type name) => instance made through the registry (counted per type)
  std::unique_ptr<devs::AtomicBase> create(const TypeInfo& type, const std::string& name,
                                           const Params& params);
  // () => how many instances of each type were made (types never made are absent)
  std::map<std::string, std::size_t> instantiated() const;

 private:
  std::map<std::string, TypeInfo, std::less<>> types_;
  std::map<std::string, std::size_t> made_;
};

struct Registrar {
  explicit Registrar(TypeInfo info) { Registry::instance().add(std::move(info)); }
};

}  // namespace yardsim::models

#define YARDSIM_REGISTER_TYPE(ident, ...) \
  static const ::yardsim::models::Registrar yardsimRegistrar_##ident { __VA_ARGS__ }
