#pragma once
// The report's JavaScript (report/dist/report.js, built by esbuild from report/src), embedded
// at build time (models/CMakeLists.txt).
#include <string_view>

namespace yardsim::output {

std::string_view reportBundle();

}  // namespace yardsim::output
