#include "studies/sweep_mpi.hpp"

// the C API only: no C++ bindings (deprecated, and warnings under -Werror)
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#include <cstdlib>
#include <deque>
#include <memory>

#include "studies/sweep_pool.hpp"

namespace yardsim::studies {

namespace {
constexpr int kRequest = 1;  // worker => rank 0: give me a case
constexpr int kAssign = 2;   // rank 0 => worker: a case number, or -1: no more

// (name) => whether the environment variable is set to an integer > 1
bool moreThanOne(const char* name) {
  const char* v = std::getenv(name);
  return v && std::atoi(v) > 1;
}

// (all cases, id) => that case
const SweepCase& byId(const std::vector<SweepCase>& all, long id) {
  return all.at(static_cast<std::size_t>(id));
}

// (spec, all, OUT, rank) => cases asked of rank 0 and run until it says there are none left
void work(const SweepSpec& spec, const std::vector<SweepCase>& all,
          const std::filesystem::path& out, int rank) {
  for (;;) {
    int ask = rank;
    MPI_Send(&ask, 1, MPI_INT, 0, kRequest, MPI_COMM_WORLD);
    long id = -1;
    MPI_Recv(&id, 1, MPI_LONG, 0, kAssign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (id < 0) return;
    CaseProcess p(spec, byId(all, id), out, rank);
    while (!p.poll()) pollPause();
  }
}
}  // namespace

bool launchedByMpi() {
  return moreThanOne("OMPI_COMM_WORLD_SIZE") || moreThanOne("PMI_SIZE") ||
         moreThanOne("PMIX_SIZE") || moreThanOne("MPI_LOCALNRANKS");
}

MpiSession::MpiSession() {
  MPI_Init(nullptr, nullptr);
  MPI_Comm_rank(MPI_COMM_WORLD, &world_.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &world_.size);
}

MpiSession::~MpiSession() {
  MPI_Finalize();
}

void MpiSession::barrier() const {
  MPI_Barrier(MPI_COMM_WORLD);
}

bool MpiSession::broadcast(bool flag) const {
  int v = flag ? 1 : 0;
  MPI_Bcast(&v, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return v != 0;
}

void runMpiSchedule(const MpiSession& session, const SweepSpec& spec,
                    const std::vector<SweepCase>& all, const std::vector<SweepCase>& todo,
                    const std::filesystem::path& out,
                    const std::function<void(const CaseRecord&)>& onDone) {
  const MpiWorld w = session.world();
  if (w.rank != 0) {
    work(spec, all, out, w.rank);
    session.barrier();
    return;
  }
  std::deque<long> queue;
  for (const auto& c : todo) queue.push_back(static_cast<long>(c.id));
  std::unique_ptr<CaseProcess> own;
  int stopped = 0;
  // (requests, own slot) => each asking rank served the next case; rank 0 runs one case at a time
  while (stopped < w.size - 1 || !queue.empty() || own) {
    int flag = 0;
    MPI_Status st;
    bool busy = false;
    while (MPI_Iprobe(MPI_ANY_SOURCE, kRequest, MPI_COMM_WORLD, &flag, &st), flag) {
      int who = 0;
      MPI_Recv(&who, 1, MPI_INT, st.MPI_SOURCE, kRequest, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      long id = -1;
      if (!queue.empty()) {
        id = queue.front();
        queue.pop_front();
      } else {
        ++stopped;
      }
      MPI_Send(&id, 1, MPI_LONG, st.MPI_SOURCE, kAssign, MPI_COMM_WORLD);
      busy = true;
    }
    if (!own && !queue.empty()) {
      own = std::make_unique<CaseProcess>(spec, byId(all, queue.front()), out, 0);
      queue.pop_front();
    }
    if (own)
      if (auto r = own->poll()) {
        if (onDone) onDone(*r);
        own.reset();
        busy = true;
      }
    if (!busy) pollPause();
  }
  session.barrier();
}

}  // namespace yardsim::studies
