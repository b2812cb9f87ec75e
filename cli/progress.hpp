#pragma once
// Run progress: on a terminal, one line redrawn at most 10 times a second (percentage of
// simulated time, real-time factor, ETA); otherwise a plain log line every 5 s.
#include "run/runner.hpp"

namespace yardsim::cli {

class ProgressPrinter {
 public:
  ProgressPrinter();
  void operator()(const run::Progress& p);
  // () => the terminal line ended (call once when the run is over)
  void finish();

 private:
  bool tty_;
  double lastLog_ = 0.0;
  bool drawn_ = false;
};

}  // namespace yardsim::cli
