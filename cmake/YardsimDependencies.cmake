# Finds every third-party package through its CONFIG package. A missing one stops configure
# with the Debian package that provides it (scripts/setup.sh installs them all).
macro(yardsim_require package debian)
  find_package(${package} CONFIG QUIET ${ARGN})
  if(NOT ${package}_FOUND)
    message(FATAL_ERROR
      "yardsim: CMake package '${package}' not found. Install the Debian package '${debian}' "
      "(sudo apt-get install --no-install-recommends ${debian}), or run scripts/setup.sh.")
  endif()
endmacro()

yardsim_require(Eigen3 libeigen3-dev)
yardsim_require(Boost libboost-graph-dev COMPONENTS graph)
yardsim_require(SUNDIALS libsundials-dev)
yardsim_require(fcl libfcl-dev)
yardsim_require(yaml-cpp libyaml-cpp-dev)
yardsim_require(spdlog libspdlog-dev)
yardsim_require(CLI11 libcli11-dev)
# the yard's database (yard/): SQLite through CMake's own find module
find_package(SQLite3 QUIET)
if(NOT SQLite3_FOUND)
  message(FATAL_ERROR "yardsim: SQLite3 not found. Install the Debian package 'libsqlite3-dev' "
    "(sudo apt-get install --no-install-recommends libsqlite3-dev), or run scripts/setup.sh.")
endif()
# Dense eigenvalues of a few thousand rows (the time-domain Rankine solver's growth check,
# forces/hydro/dense_eigenvalues): LAPACK's DGEEV from OpenBLAS, through CMake's own find module
set(BLA_VENDOR OpenBLAS)
find_package(LAPACK QUIET)
unset(BLA_VENDOR)
if(NOT LAPACK_FOUND)
  message(FATAL_ERROR "yardsim: OpenBLAS's LAPACK not found. Install the Debian package 'libopenblas-dev' "
    "(sudo apt-get install --no-install-recommends libopenblas-dev), or run scripts/setup.sh.")
endif()
# STEP import (forces/geometry/step_reader) through OpenCASCADE 7.6: large, so behind an option;
# ON by default (CI and scripts/setup.sh install it); OFF builds a yardsim that refuses .step files.
option(YARDSIM_WITH_STEP "Read STEP files through OpenCASCADE (libocct-data-exchange-dev)" ON)
if(YARDSIM_WITH_STEP)
  find_package(OpenCASCADE CONFIG QUIET)
  if(NOT OpenCASCADE_FOUND)
    message(FATAL_ERROR
      "yardsim: OpenCASCADE not found for YARDSIM_WITH_STEP=ON. Install the Debian packages "
      "'libocct-data-exchange-dev libocct-modeling-algorithms-dev libocct-modeling-data-dev "
      "libocct-foundation-dev' (or run scripts/setup.sh), or configure with -DYARDSIM_WITH_STEP=OFF.")
  endif()
  # the OCCT toolkits the reader uses (STEP translation, tessellation, global properties)
  set(YARDSIM_OCCT_LIBRARIES TKSTEP TKXSBase TKMesh TKTopAlgo TKBRep TKG3d TKMath TKernel)
endif()
# Sweep results (HDF5, C API) and the MPI sweep engine (Open MPI): Debian's module packages,
# whose find modules test-compile C
enable_language(C)
find_package(HDF5 QUIET COMPONENTS C)
if(NOT HDF5_FOUND)
  message(FATAL_ERROR "yardsim: HDF5 not found. Install the Debian package 'libhdf5-dev' "
    "(sudo apt-get install --no-install-recommends libhdf5-dev), or run scripts/setup.sh.")
endif()
find_package(MPI QUIET COMPONENTS C)
if(NOT MPI_C_FOUND)
  message(FATAL_ERROR "yardsim: MPI not found. Install the Debian packages 'libopenmpi-dev openmpi-bin' "
    "(sudo apt-get install --no-install-recommends libopenmpi-dev openmpi-bin), or run scripts/setup.sh.")
endif()
if(YARDSIM_BUILD_TESTS)
  yardsim_require(Catch2 catch2)
endif()
if(YARDSIM_BUILD_BENCH)
  yardsim_require(benchmark libbenchmark-dev)
endif()
