#include "models/params.hpp"

#include <cmath>
#include <stdexcept>

namespace yardsim::models {

std::string describe(ParamKind kind) {
  switch (kind) {
    case ParamKind::Number: return "a number";
    case ParamKind::Integer: return "an integer";
    case ParamKind::Boolean: return "true or false";
    case ParamKind::String: return "a string";
    case ParamKind::NumberList: return "a list of numbers";
    case ParamKind::StringList: return "a list of strings";
    case ParamKind::Map: return "a mapping";
    case ParamKind::Any: return "any value";
  }
  return "?";
}

namespace {
template <class T>
bool converts(const YAML::Node& n) {
  T out;
  return n.IsScalar() && YAML::convert<T>::decode(n, out);
}
// (node) => a finite number (NaN and infinities are refused at the door: they only ever hang or
// poison a run)
bool finiteNumber(const YAML::Node& n) {
  double out = 0.0;
  return n.IsScalar() && YAML::convert<double>::decode(n, out) && std::isfinite(out);
}
}  // namespace

bool hasKind(const YAML::Node& v, ParamKind kind) {
  switch (kind) {
    case ParamKind::Number: return finiteNumber(v);
    case ParamKind::Integer: return converts<long long>(v);
    case ParamKind::Boolean: return converts<bool>(v);
    case ParamKind::String: return v.IsScalar();
    case ParamKind::NumberList:
      if (!v.IsSequence()) return false;
      for (const auto& e : v)
        if (!finiteNumber(e)) return false;
      return true;
    case ParamKind::StringList:
      if (!v.IsSequence()) return false;
      for (const auto& e : v)
        if (!e.IsScalar()) return false;
      return true;
    case ParamKind::Map: return v.IsMap();
    case ParamKind::Any: return v.IsDefined();
  }
  return false;
}

const YAML::Node& Params::at(const std::string& name) const {
  auto it = values_.find(name);
  if (it == values_.end()) throw std::out_of_range("parameter '" + name + "' is not set");
  return it->second;
}

SourceMark Params::mark(const std::string& name) const {
  auto it = marks_.find(name);
  return it == marks_.end() ? SourceMark{} : it->second;
}

void Params::set(const std::string& name, YAML::Node value, SourceMark where) {
  values_[name] = std::move(value);
  marks_[name] = std::move(where);
}

void ParamCheck::error(const std::string& param, const std::string& message) {
  failed_ = true;
  diags_.error(params_.mark(param), keyPath_ + "." + param, message);
}

void ParamCheck::errorAt(const std::string& param, const YAML::Node& node,
                         const std::string& subKey, const std::string& message,
                         const std::string& hint) {
  failed_ = true;
  SourceMark where = params_.mark(param);
  const YAML::Mark m = node.Mark();
  if (node.IsDefined() && !m.is_null()) {
    where.line = m.line + 1;
    where.column = m.column + 1;
  }
  diags_.error(where, keyPath_ + "." + param + (subKey.empty() ? "" : "." + subKey), message, hint);
}

}  // namespace yardsim::models
