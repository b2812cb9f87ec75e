#include "support/test_paths.hpp"

namespace yardsim::test {

// (YARDSIM_TEST_* of this build, tests/CMakeLists.txt) => the folders
const char* sourceDir() { return YARDSIM_TEST_SOURCE_DIR; }
const char* binaryDir() { return YARDSIM_TEST_BINARY_DIR; }
const char* python3() { return YARDSIM_TEST_PYTHON3; }

}  // namespace yardsim::test
