#include "models/diagnostics.hpp"

#include <algorithm>

namespace yardsim::models {

std::string format(const Diagnostic& d) {
  std::string out = d.where.file;
  if (d.where.line > 0) out += ":" + std::to_string(d.where.line) + ":" + std::to_string(d.where.column);
  out += d.severity == Diagnostic::Severity::Error ? ": error: " : ": warning: ";
  if (!d.keyPath.empty()) out += d.keyPath + ": ";
  out += d.message;
  if (!d.hint.empty()) out += " (" + d.hint + ")";
  return out;
}

void Diagnostics::error(SourceMark where, std::string keyPath, std::string message,
                        std::string hint) {
  list_.push_back({Diagnostic::Severity::Error, std::move(where), std::move(keyPath),
                   std::move(message), std::move(hint)});
  ++errors_;
}

void Diagnostics::warning(SourceMark where, std::string keyPath, std::string message,
                          std::string hint, std::string element, double value) {
  list_.push_back({Diagnostic::Severity::Warning, std::move(where), std::move(keyPath),
                   std::move(message), std::move(hint), std::move(element), value});
}

std::string Diagnostics::report() const {
  std::string out;
  for (const auto& d : list_) out += format(d) + "\n";
  return out;
}

namespace {
// (a, b) => Levenshtein distance, case-insensitive
std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (same ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}
}  // namespace

std::string didYouMean(std::string_view name, const std::vector<std::string>& candidates) {
  std::size_t best = std::string::npos;
  const std::string* pick = nullptr;
  for (const auto& c : candidates) {
    const std::size_t d = editDistance(name, c);
    if (d < best) {
      best = d;
      pick = &c;
    }
  }
  const std::size_t limit = std::max<std::size_t>(2, name.size() / 3);
  if (pick && best > limit) {
    // a truncated or extended name ("out" for "output") is still a near miss
    const std::string_view a = name, b = *pick;
    const bool prefix = std::min(a.size(), b.size()) >= 2 &&
                        (a.substr(0, b.size()) == b || b.substr(0, a.size()) == a);
    if (!prefix) pick = nullptr;
  }
  if (!pick) return {};
  return "did you mean '" + *pick + "'?";
}

}  // namespace yardsim::models
