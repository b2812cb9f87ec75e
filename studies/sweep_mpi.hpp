#pragma once
// The MPI engine of `yardsim sweep` (`mpirun -n N yardsim sweep SWEEP -o OUT`): rank 0 hands out
// case numbers one at a time to whichever rank asks (dynamic load balancing: cases differ in
// length) and runs cases itself between requests; every rank runs its cases in child processes
// (sweep_pool.hpp) that write their own records under OUT/cases/, so a rank that dies loses
// only its running case, which a resume runs again.
#include <filesystem>
#include <functional>
#include <memory>
#include <vector>

#include "studies/mpi_module.hpp"
#include "studies/sweep_case.hpp"

namespace yardsim::studies {

// () => whether mpirun/srun started this process as one of several MPI ranks (environment)
bool launchedByMpi();

// Initialises MPI on construction (Open MPI loaded then: mpi_module.hpp) and finalises it on
// destruction.
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  MpiWorld world() const { return comm_->world(); }
  // () => every rank reached this point
  void barrier() const { comm_->barrier(); }
  // (rank 0's flag) => the same flag on every rank
  bool broadcast(bool flag) const { return comm_->broadcast(flag ? 1 : 0) != 0; }
  const MpiComm& comm() const { return *comm_; }

 private:
  std::unique_ptr<MpiComm> comm_;
};

// (session, spec, cases still to run (read on rank 0 only), OUT, on each of rank 0's own results)
// => every case run by some rank; returns on every rank once all are recorded
void runMpiSchedule(const MpiSession& session, const SweepSpec& spec,
                    const std::vector<SweepCase>& all, const std::vector<SweepCase>& todo,
                    const std::filesystem::path& out,
                    const std::function<void(const CaseRecord&)>& onDone);

}  // namespace yardsim::studies
