// The MPI engine's launch detection (the engine itself runs under mpirun in
// tests/cli/sweep_command_test.cpp: its table equals the local one).
#include <catch2/catch.hpp>
#include <cstdlib>

#include "studies/sweep_mpi.hpp"
#include "support/loaded_objects.hpp"

using namespace yardsim::studies;

TEST_CASE("A process is an MPI rank when mpirun or srun started several") {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE", "MPI_LOCALNRANKS"})
    unsetenv(v);
  CHECK_FALSE(launchedByMpi());
  setenv("OMPI_COMM_WORLD_SIZE", "1", 1);
  CHECK_FALSE(launchedByMpi());  // a singleton needs no scheduler
  setenv("OMPI_COMM_WORLD_SIZE", "4", 1);
  CHECK(launchedByMpi());
  unsetenv("OMPI_COMM_WORLD_SIZE");
  setenv("PMI_SIZE", "2", 1);
  CHECK(launchedByMpi());
  unsetenv("PMI_SIZE");
}

TEST_CASE("Open MPI is not loaded by a process that starts no MPI session") {
  // (each test case runs in its own process under ctest) => libyardsim_studies.so is linked and
  // loaded, Open MPI is not: the MPI module (studies/mpi_module.hpp) opens it for a session
  CHECK(yardsim::testing::loaded("libyardsim_studies"));
  CHECK_FALSE(yardsim::testing::loaded("libmpi"));
  CHECK_FALSE(yardsim::testing::loaded("libyardsim_mpi"));
}

TEST_CASE("A missing MPI module is an error naming it and the fix") {
  CHECK_THROWS_WITH(loadMpiModule("/nonexistent-folder/libyardsim_mpi.so"),
                    Catch::Contains("/nonexistent-folder/libyardsim_mpi.so") &&
                        Catch::Contains("reinstall yardsim"));
}
