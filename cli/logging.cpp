#include "cli/logging.hpp"

#include <spdlog/cfg/env.h>
#include <spdlog/sinks/stdout_color_sinks.h>

namespace yardsim::cli {

void setupLogging() {
  for (const char* layer : {"devs", "dtss", "dynamics", "forces", "collision", "models", "cli"})
    if (!spdlog::get(layer)) {
      auto l = spdlog::stderr_color_mt(layer);
      l->set_pattern("[%H:%M:%S.%e] [%n] [%l] %v");
    }
  spdlog::cfg::load_env_levels();
}

std::shared_ptr<spdlog::logger> logger(const char* layer) {
  auto l = spdlog::get(layer);
  if (!l) {
    setupLogging();
    l = spdlog::get(layer);
  }
  return l;
}

}  // namespace yardsim::cli
