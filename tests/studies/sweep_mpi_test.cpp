// The MPI engine's launch detection (the engine itself runs under mpirun in
// tests/cli/sweep_command_test.cpp: its table equals the local one).
#include <catch2/catch.hpp>
#include <cstdlib>

#include "studies/sweep_mpi.hpp"

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
