#pragma once
// A run that failed numerically (NaN, blow-up, violated constraint): names the model or
// element, the time, what happened and a suggestion. The CLI exits with status 2.
#include <string>

#include "devs/simulator.hpp"

namespace yardsim::models {

class NumericalError : public devs::SimulationError {
 public:
  NumericalError(const std::string& where, double t, const std::string& what,
                 const std::string& suggestion)
      : devs::SimulationError(where + " at t = " + std::to_string(t) + " s: " + what +
                              (suggestion.empty() ? "" : "; suggestion: " + suggestion)) {}
};

}  // namespace yardsim::models
