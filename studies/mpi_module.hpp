#pragma once
// The MPI sweep's Open MPI code lives in a module, libyardsim_mpi.so, installed beside
// libyardsim_studies.so and opened (dlopen) when `yardsim sweep` runs under mpirun/srun, so no
// other run loads Open MPI (its libraries' symbol bindings are part of every start-up otherwise;
// docs/performance.md). This header is the seam: the few MPI calls the sweep makes, the
// module's one entry and the loader.
#include <memory>
#include <string>

namespace yardsim::studies {

struct MpiWorld {
  int rank = 0, size = 1;
};

// MPI_COMM_WORLD after MPI_Init; its destructor calls MPI_Finalize.
class MpiComm {
 public:
  virtual ~MpiComm() = default;
  virtual MpiWorld world() const = 0;
  // () => every rank reached this point
  virtual void barrier() const = 0;
  // (rank 0's value) => the same value on every rank
  virtual int broadcast(int value) const = 0;
  // (value, destination rank, tag) => sent (blocking)
  virtual void sendInt(int value, int to, int tag) const = 0;
  virtual void sendLong(long value, int to, int tag) const = 0;
  // (source rank, tag) => the value received (blocking)
  virtual int receiveInt(int from, int tag) const = 0;
  virtual long receiveLong(int from, int tag) const = 0;
  // (tag) => the rank a message with that tag waits from, or -1 when none waits
  virtual int waiting(int tag) const = 0;
};

// (communicator out) => MPI initialised, out its world
using MpiInitEntry = void (*)(std::unique_ptr<MpiComm>& comm);

// () => the module this build loads: libyardsim_mpi.so beside libyardsim_studies.so; empty in a
// static build (linked in)
std::string mpiModulePath();

// (module file) => its entry `yardsim_mpi_init`, the module kept loaded (its symbols global:
// Open MPI opens its own components, which need them). Throws std::runtime_error naming the
// file and why.
MpiInitEntry loadMpiModule(const std::string& file);

}  // namespace yardsim::studies

// (communicator out) => the entry itself, defined by mpi_module.cpp
extern "C" void yardsim_mpi_init(std::unique_ptr<yardsim::studies::MpiComm>& comm);
