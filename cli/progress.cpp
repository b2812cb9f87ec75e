#include "cli/progress.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>

#include "cli/logging.hpp"

namespace yardsim::cli {

ProgressPrinter::ProgressPrinter() : tty_(isatty(STDERR_FILENO) != 0) {}

void ProgressPrinter::operator()(const run::Progress& p) {
  const bool bounded = std::isfinite(p.until) && p.until > 0;
  const double frac = bounded ? std::min(1.0, p.t / p.until) : 0.0;
  const double rtf = p.wall > 0 ? p.t / p.wall : 0.0;
  const double eta = (frac > 0 && frac < 1) ? p.wall * (1.0 - frac) / frac : 0.0;
  char line[160];
  if (bounded)
    std::snprintf(line, sizeof line, "%5.1f%%  t = %.4g / %.4g s  real-time factor %.3g  ETA %.1f s",
                  100.0 * frac, p.t, p.until, rtf, eta);
  else
    std::snprintf(line, sizeof line, "t = %.4g s  real-time factor %.3g", p.t, rtf);
  if (tty_) {
    std::fprintf(stderr, "\r\033[K%s", line);
    std::fflush(stderr);
    drawn_ = true;
  } else if (p.wall - lastLog_ >= 5.0) {
    lastLog_ = p.wall;
    logger("cli")->info("progress: {}", line);
  }
}

void ProgressPrinter::finish() {
  if (tty_ && drawn_) std::fprintf(stderr, "\n");
}

}  // namespace yardsim::cli
