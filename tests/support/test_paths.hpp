#pragma once
// Where the tests find the project: the source and build folders and the Python with h5py.
// The values are compiled into one small library per build (tests/support/test_paths.cpp,
// YARDSIM_TEST_* definitions), not into every test file, so that a test file's compile line is
// the same in every checkout and a compiler cache shared by two checkouts serves both (.ci/run).

namespace yardsim::test {
// () => the project's source folder, absolute, e.g. "/home/me/yardsim"
const char* sourceDir();
// () => the build folder, absolute
const char* binaryDir();
// () => the python3 the HDF5 tests run (CMake's YARDSIM_PYTHON3)
const char* python3();
}  // namespace yardsim::test

#define YARDSIM_SOURCE_DIR (::yardsim::test::sourceDir())
#define YARDSIM_BINARY_DIR (::yardsim::test::binaryDir())
#define YARDSIM_PYTHON3 (::yardsim::test::python3())
