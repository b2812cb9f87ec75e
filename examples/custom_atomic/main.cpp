// The yardsim command, with this project's model types registered (peak_monitor.cpp).
#include "cli/yardsim_main.hpp"

int main(int argc, char** argv) { return yardsim::cli::yardsimMain(argc, argv); }
