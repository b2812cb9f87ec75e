#pragma once
// Errors and warnings about a scene, each pinned to file:line:column and a key path, collected
// so that every mistake of a file is reported at once, before anything runs.
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace yardsim::models {

// Where a diagnostic points: a file and a 1-based line and column (0 when unknown).
struct SourceMark {
  std::string file;
  int line = 0;
  int column = 0;
};

struct Diagnostic {
  enum class Severity { Error, Warning };
  Severity severity = Severity::Error;
  SourceMark where;
  std::string keyPath;  // e.g. components.crane1.params.speed
  std::string message;  // what is wrong and what was expected
  std::string hint;     // e.g. "did you mean 'speed'?"
  // a warning that names a mechanical element (the stiffness guard: the stiffest body) and a
  // value (its omega_max dt): run.json's alarms show them (run/alarms.hpp); "" and NaN otherwise
  std::string element = {};
  double value = std::numeric_limits<double>::quiet_NaN();
};

// (diagnostic) => "file:line:col: error: components.x.type: message (did you mean 'y'?)"
std::string format(const Diagnostic& d);

class Diagnostics {
 public:
  void error(SourceMark where, std::string keyPath, std::string message, std::string hint = {});
  void warning(SourceMark where, std::string keyPath, std::string message, std::string hint = {},
               std::string element = {}, double value = std::numeric_limits<double>::quiet_NaN());
  bool hasErrors() const { return errors_ > 0; }
  std::size_t errorCount() const { return errors_; }
  const std::vector<Diagnostic>& all() const { return list_; }
  // () => every diagnostic, one formatted line each
  std::string report() const;

 private:
  std::vector<Diagnostic> list_;
  std::size_t errors_ = 0;
};

// A scene that failed validation: carries all its diagnostics.
class SceneError : public std::runtime_error {
 public:
  explicit SceneError(Diagnostics d) : std::runtime_error(d.report()), diagnostics(std::move(d)) {}
  Diagnostics diagnostics;
};

// (misspelt name, candidates) => "did you mean 'x'?" for the closest candidate within a small
// edit distance, or an empty string
std::string didYouMean(std::string_view name, const std::vector<std::string>& candidates);

}  // namespace yardsim::models
