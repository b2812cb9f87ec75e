// The module libyardsim_mpi.so (mpi_module.hpp): the sweep's MPI calls on Open MPI's C API.
#include "studies/mpi_module.hpp"

// the C API only: no C++ bindings (deprecated, and warnings under -Werror)
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>

namespace yardsim::studies {

namespace {

class OpenMpiComm final : public MpiComm {
 public:
  OpenMpiComm() {
    MPI_Init(nullptr, nullptr);
    MPI_Comm_rank(MPI_COMM_WORLD, &world_.rank);
    MPI_Comm_size(MPI_COMM_WORLD, &world_.size);
  }
  ~OpenMpiComm() override { MPI_Finalize(); }
  OpenMpiComm(const OpenMpiComm&) = delete;
  OpenMpiComm& operator=(const OpenMpiComm&) = delete;

  MpiWorld world() const override { return world_; }
  void barrier() const override { MPI_Barrier(MPI_COMM_WORLD); }
  int broadcast(int value) const override {
    MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
    return value;
  }
  void sendInt(int value, int to, int tag) const override {
    MPI_Send(&value, 1, MPI_INT, to, tag, MPI_COMM_WORLD);
  }
  void sendLong(long value, int to, int tag) const override {
    MPI_Send(&value, 1, MPI_LONG, to, tag, MPI_COMM_WORLD);
  }
  int receiveInt(int from, int tag) const override {
    int value = 0;
    MPI_Recv(&value, 1, MPI_INT, from, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return value;
  }
  long receiveLong(int from, int tag) const override {
    long value = 0;
    MPI_Recv(&value, 1, MPI_LONG, from, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return value;
  }
  int waiting(int tag) const override {
    int flag = 0;
    MPI_Status st;
    MPI_Iprobe(MPI_ANY_SOURCE, tag, MPI_COMM_WORLD, &flag, &st);
    return flag ? st.MPI_SOURCE : -1;
  }

 private:
  MpiWorld world_;
};

}  // namespace

}  // namespace yardsim::studies

extern "C" void yardsim_mpi_init(std::unique_ptr<yardsim::studies::MpiComm>& comm) {
  comm = std::make_unique<yardsim::studies::OpenMpiComm>();
}
