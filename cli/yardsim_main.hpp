#pragma once
// The whole `yardsim` command as a function, so a project that registers its own model types
// can build its own executable around it (examples/custom_atomic).
namespace yardsim::cli {

// (argc, argv) => exit status (see exit_codes.hpp)
int yardsimMain(int argc, char** argv);

}  // namespace yardsim::cli
