#pragma once
// YARDSIM_FLATTEN: [[gnu::flatten]] (inline every call in the function's body, so small Eigen
// products stay inline), except in the sanitizer build (YARDSIM_NO_FLATTEN, set by
// -DYARDSIM_SANITIZE=ON), where the instrumented, fully inlined kernels take minutes to compile.
#if defined(YARDSIM_NO_FLATTEN)
#define YARDSIM_FLATTEN
#else
#define YARDSIM_FLATTEN [[gnu::flatten]]
#endif
