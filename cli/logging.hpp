#pragma once
// One spdlog logger per layer (devs, dtss, dynamics, forces, collision, models, cli), writing to
// stderr; SPDLOG_LEVEL (e.g. SPDLOG_LEVEL=debug or SPDLOG_LEVEL=models=debug) is honoured.
#include <memory>

#include <spdlog/spdlog.h>

namespace yardsim::cli {

void setupLogging();
// (layer name) => its logger
std::shared_ptr<spdlog::logger> logger(const char* layer);

}  // namespace yardsim::cli
