#pragma once
// The yardsim command's exit statuses (README.md, "Exit codes").
namespace yardsim::cli {
inline constexpr int kOk = 0;
inline constexpr int kInvalidInput = 1;      // bad scene or arguments: nothing was simulated
inline constexpr int kNumericalFailure = 2;  // the run failed numerically; output kept on disk
inline constexpr int kInternalError = 3;     // a bug or an environment problem
inline constexpr int kAlarm = 4;             // the run raised an alarm and --fail-on alarm was given
}  // namespace yardsim::cli
