// peer_multibody LIB ALGO MODEL N      => one JSON line: the time of one kernel call
// peer_multibody --check MODEL N       => exit 0 if every library computes the same thing
// peer_multibody LIB ALGO MODEL N REPS => exactly REPS calls, untimed (for callgrind's counts)
// LIB: yardsim, rbdl, pinocchio (LOCAL convention), pinocchio-world (WORLD convention for ABA
// and CRBA); ALGO: aba, rnea, crba (mass matrix and its Cholesky factor); MODEL: chain, tree
// (peer_models.hpp). A process times one case: a warm-up, then 7 batches of at least 5 ms
// of this thread's CPU time (CLOCK_THREAD_CPUTIME_ID: time the core spent on other processes
// of a busy machine is not counted), and prints the median and the minimum ns per call;
// bench/compare.sh runs the libraries' processes alternately. --check is the proof that the models
// agree: RNEA, ABA and the mass matrix of every library against yardsim's on a random state (the
// tree's root at the identity and at rest, where the libraries' free-joint conventions coincide up
// to the order of the velocity components), to 1e-9 relative.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include "kernel.hpp"

using namespace yardsim::bench::peers;

namespace {

// (lib, spec, state) => that library's kernel; nullptr when it was not built in
std::unique_ptr<Kernel> make(const std::string& lib, const std::vector<BodySpec>& spec,
                             const NeutralState& s) {
  if (lib == "yardsim") return makeYardsim(spec, s);
#ifdef YARDSIM_PEERS_HAVE_RBDL
  if (lib == "rbdl") return makeRbdl(spec, s);
#endif
#ifdef YARDSIM_PEERS_HAVE_PINOCCHIO
  if (lib == "pinocchio") return makePinocchio(spec, s, false);
  if (lib == "pinocchio-world") return makePinocchio(spec, s, true);
#endif
  return nullptr;
}

// () => this thread's CPU time, ns
double threadCpuNs() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return 1e9 * static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec);
}

// (kernel, algo) => median and minimum CPU ns per call over 7 batches of >= 5 ms
std::pair<double, double> timeKernel(Kernel& k, const std::string& algo) {
  void (Kernel::*call)() = algo == "aba"    ? &Kernel::aba
                           : algo == "rnea" ? &Kernel::rnea
                                            : &Kernel::crbaChol;
  long reps = 1;
  for (;;) {  // calibrate: reps per batch such that a batch takes >= 5 ms
    const double t0 = threadCpuNs();
    for (long i = 0; i < reps; ++i) (k.*call)();
    if (threadCpuNs() - t0 >= 5e6) break;
    reps *= 2;
  }
  std::vector<double> ns;
  for (int b = 0; b < 7; ++b) {
    const double t0 = threadCpuNs();
    for (long i = 0; i < reps; ++i) (k.*call)();
    ns.push_back((threadCpuNs() - t0) / static_cast<double>(reps));
  }
  std::sort(ns.begin(), ns.end());
  return {ns[ns.size() / 2], ns.front()};
}

double relErr(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).norm() / std::max(1.0, b.norm());
}

// (model, N) => 0 when every built library agrees with yardsim, 1 otherwise (report on stdout)
int check(const std::string& model, int n) {
  const auto spec = modelSpec(model, n);
  const NeutralState s = randomState(spec, 7, true);
  auto ref = make("yardsim", spec, s);
  ref->rnea();
  ref->aba();
  ref->crbaChol();
  int bad = 0;
  for (const char* lib : {"rbdl", "pinocchio", "pinocchio-world"}) {
    auto k = make(lib, spec, s);
    if (!k) {
      std::printf("%s: not built, skipped\n", lib);
      continue;
    }
    k->rnea();
    k->aba();
    k->crbaChol();
    const double e[3] = {relErr(k->tauNeutral(), ref->tauNeutral()),
                         relErr(k->ddqNeutral(), ref->ddqNeutral()),
                         relErr(k->massNeutral(), ref->massNeutral())};
    const bool ok = e[0] < 1e-9 && e[1] < 1e-9 && e[2] < 1e-9;
    std::printf("%s %s(%d) against yardsim: rnea %.2e aba %.2e mass matrix %.2e %s\n", lib,
                model.c_str(), n, e[0], e[1], e[2], ok ? "ok" : "DIFFERENT");
    bad += ok ? 0 : 1;
  }
  return bad == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc == 4 && std::strcmp(argv[1], "--check") == 0)
      return check(argv[2], std::stoi(argv[3]));
    if (argc != 5 && argc != 6) {
      std::fprintf(stderr,
                   "usage: peer_multibody yardsim|rbdl|pinocchio|pinocchio-world aba|rnea|crba "
                   "chain|tree N [REPS]\n"
                   "       peer_multibody --check chain|tree N\n");
      return 2;
    }
    const std::string lib = argv[1], algo = argv[2], model = argv[3];
    const int n = std::stoi(argv[4]);
    if (algo != "aba" && algo != "rnea" && algo != "crba")
      throw std::invalid_argument("ALGO must be aba, rnea or crba");
    const auto spec = modelSpec(model, n);
    auto k = make(lib, spec, randomState(spec, 42, false));
    if (!k) {
      std::fprintf(stderr,
                   "peer_multibody: library %s not built in (see bench/peers/build_peers.sh)\n",
                   lib.c_str());
      return 2;
    }
    if (argc == 6) {
      const long reps = std::stol(argv[5]);
      for (long i = 0; i < reps; ++i)
        algo == "aba" ? k->aba() : algo == "rnea" ? k->rnea() : k->crbaChol();
      return 0;
    }
    const auto [median, min] = timeKernel(*k, algo);
    std::printf(
        "{\"lib\":\"%s\",\"algo\":\"%s\",\"model\":\"%s\",\"n\":%d,\"ns\":%.2f,\"ns_min\":%.2f}\n",
        lib.c_str(), algo.c_str(), model.c_str(), n, median, min);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "peer_multibody: error: %s\n", e.what());
    return 2;
  }
}
