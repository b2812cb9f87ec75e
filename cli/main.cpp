#include "cli/yardsim_main.hpp"

int main(int argc, char** argv) { return yardsim::cli::yardsimMain(argc, argv); }
