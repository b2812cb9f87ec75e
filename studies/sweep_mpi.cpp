#include "studies/sweep_mpi.hpp"

#include <cstdlib>
#include <deque>
#include <memory>

#include "output/module_loader.hpp"
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

// (communicator, spec, all, OUT, rank) => cases asked of rank 0 and run until it says there are
// none left
void work(const MpiComm& comm, const SweepSpec& spec, const std::vector<SweepCase>& all,
          const std::filesystem::path& out, int rank) {
  for (;;) {
    comm.sendInt(rank, 0, kRequest);
    const long id = comm.receiveLong(0, kAssign);
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

std::string mpiModulePath() {
#ifndef YARDSIM_MPI_LINKED
  return output::moduleBeside(reinterpret_cast<const void*>(&mpiModulePath), "libyardsim_mpi.so");
#else
  return {};
#endif
}

MpiInitEntry loadMpiModule(const std::string& file) {
  return reinterpret_cast<MpiInitEntry>(output::openModuleEntry(
      file, "yardsim_mpi_init", "the MPI module",
      "; the MPI module is built and installed with yardsim (reinstall yardsim, or put the module "
      "back beside libyardsim_studies.so)",
      true));
}

MpiSession::MpiSession() {
#ifdef YARDSIM_MPI_LINKED
  yardsim_mpi_init(comm_);
#else
  loadMpiModule(mpiModulePath())(comm_);
#endif
}

MpiSession::~MpiSession() = default;

void runMpiSchedule(const MpiSession& session, const SweepSpec& spec,
                    const std::vector<SweepCase>& all, const std::vector<SweepCase>& todo,
                    const std::filesystem::path& out,
                    const std::function<void(const CaseRecord&)>& onDone) {
  const MpiWorld w = session.world();
  const MpiComm& comm = session.comm();
  if (w.rank != 0) {
    work(comm, spec, all, out, w.rank);
    session.barrier();
    return;
  }
  std::deque<long> queue;
  for (const auto& c : todo) queue.push_back(static_cast<long>(c.id));
  std::unique_ptr<CaseProcess> own;
  int stopped = 0;
  // (requests, own slot) => each asking rank served the next case; rank 0 runs one case at a time
  while (stopped < w.size - 1 || !queue.empty() || own) {
    bool busy = false;
    for (int from = comm.waiting(kRequest); from >= 0; from = comm.waiting(kRequest)) {
      comm.receiveInt(from, kRequest);
      long id = -1;
      if (!queue.empty()) {
        id = queue.front();
        queue.pop_front();
      } else {
        ++stopped;
      }
      comm.sendLong(id, from, kAssign);
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
