#pragma once
// The parameters of one component, after `$name` references are resolved: declared by the
// component's type (ParamSpec: name, kind, required or default, unit), checked against that
// declaration when the scene is loaded, then read by the type's factory.
#include <map>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "models/diagnostics.hpp"

namespace yardsim::models {

enum class ParamKind { Number, Integer, Boolean, String, NumberList, StringList, Map, Any };

// (kind) => what the scene must write, e.g. "a number" or "a list of numbers"
std::string describe(ParamKind kind);

struct ParamSpec {
  std::string name;
  ParamKind kind = ParamKind::Number;
  bool required = false;
  std::string defaultValue;  // YAML text used when the key is absent and not required
  std::string unit;          // SI unit, for list-types and docs
  std::string doc;
};

class Params {
 public:
  bool has(const std::string& name) const { return values_.count(name) > 0; }
  double number(const std::string& name) const { return at(name).as<double>(); }
  long long integer(const std::string& name) const { return at(name).as<long long>(); }
  bool boolean(const std::string& name) const { return at(name).as<bool>(); }
  std::string string(const std::string& name) const { return at(name).as<std::string>(); }
  std::vector<double> numbers(const std::string& name) const {
    return at(name).as<std::vector<double>>();
  }
  std::vector<std::string> strings(const std::string& name) const {
    return at(name).as<std::vector<std::string>>();
  }
  const YAML::Node& node(const std::string& name) const { return at(name); }
  // (name) => where the scene wrote it (for a factory's own error messages)
  SourceMark mark(const std::string& name) const;

  void set(const std::string& name, YAML::Node value, SourceMark where);
  const std::map<std::string, YAML::Node>& values() const { return values_; }

 private:
  const YAML::Node& at(const std::string& name) const;
  std::map<std::string, YAML::Node> values_;
  std::map<std::string, SourceMark> marks_;
};

// (value node, kind) => whether the node has that kind
bool hasKind(const YAML::Node& value, ParamKind kind);

// Lets a type's check function report a bad value at the place the scene wrote it.
class ParamCheck {
 public:
  ParamCheck(Diagnostics& diags, const Params& params, std::string keyPath)
      : diags_(diags), params_(params), keyPath_(std::move(keyPath)) {}
  // (parameter, message) => an error at that parameter
  void error(const std::string& param, const std::string& message);
  // (node inside parameter `param`, key path below it, message) => an error at that node
  void errorAt(const std::string& param, const YAML::Node& node, const std::string& subKey,
               const std::string& message, const std::string& hint = {});
  bool failed() const { return failed_; }

 private:
  Diagnostics& diags_;
  const Params& params_;
  std::string keyPath_;
  bool failed_ = false;
};

}  // namespace yardsim::models
