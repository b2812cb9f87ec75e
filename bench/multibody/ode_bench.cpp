// The Open Dynamics Engine (augmented / maximal-coordinate formulation) stepping the same planar
// chain as ABA/N: N rigid rods (1 kg, 1 m) joined by hinges about y, gravity along -z, dt = 1e-3.
// ODEWorldStep/N times dWorldStep (direct LCP factorisation), ODEQuickStep/N dWorldQuickStep
// (20 projected Gauss-Seidel iterations, ODE's default). EnergyDrift/ODE* measure the double
// pendulum's relative energy drift over 10 s, as yardsim's EnergyDrift/YardsimRK4.
#include <benchmark/benchmark.h>
#include <ode/ode.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "bench_models.hpp"

namespace {

struct OdeInit {
  OdeInit() { dInitODE2(0); }
  ~OdeInit() { dCloseODE(); }
  OdeInit(const OdeInit&) = delete;
  OdeInit& operator=(const OdeInit&) = delete;
};

class OdeChain {
 public:
  explicit OdeChain(int n) : world_(dWorldCreate()) {
    dWorldSetGravity(world_, 0, 0, -9.81);
    for (int i = 0; i < n; ++i) {
      dBodyID b = dBodyCreate(world_);
      dMass mass;
      dMassSetZero(&mass);
      // rod of 1 kg, 1 m along x about its centre (same as yardsim's rodInertia)
      dMassSetParameters(&mass, 1.0, 0, 0, 0, 1e-6 / 12.0, 1.0 / 12.0, 1.0 / 12.0, 0, 0, 0);
      dBodySetMass(b, &mass);
      dBodySetPosition(b, i + 0.5, 0, 0);
      dJointID j = dJointCreateHinge(world_, nullptr);
      dJointAttach(j, i == 0 ? nullptr : bodies_.back(), b);
      dJointSetHingeAnchor(j, i, 0, 0);
      dJointSetHingeAxis(j, 0, 1, 0);
      bodies_.push_back(b);
    }
  }
  ~OdeChain() { dWorldDestroy(world_); }
  OdeChain(const OdeChain&) = delete;
  OdeChain& operator=(const OdeChain&) = delete;

  dWorldID world() const { return world_; }

  /// Kinetic + potential energy (zero potential at z = 0).
  double energy() const {
    double E = 0.0;
    for (dBodyID b : bodies_) {
      const dReal* v = dBodyGetLinearVel(b);
      const dReal* w = dBodyGetAngularVel(b);
      const dReal* p = dBodyGetPosition(b);
      const dReal* R = dBodyGetRotation(b);  // 3x4 row-major
      dMass m;
      dBodyGetMass(b, &m);
      // I_world = R I R^T; w . I_world w = (R^T w) . I (R^T w)
      double wl[3];
      for (int r = 0; r < 3; ++r) wl[r] = R[0 * 4 + r] * w[0] + R[1 * 4 + r] * w[1] + R[2 * 4 + r] * w[2];
      double rot = 0.0;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) rot += wl[r] * m.I[r * 4 + c] * wl[c];
      E += 0.5 * m.mass * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) + 0.5 * rot + m.mass * 9.81 * p[2];
    }
    return E;
  }

 private:
  dWorldID world_;
  std::vector<dBodyID> bodies_;
};

const OdeInit& odeInit() {
  static const OdeInit init;
  return init;
}

// (N) => time per step of the chain released horizontally from rest; the chain is rebuilt
// (untimed) every kResetSteps steps, as in RK4Step, so that both integrate the same motion.
template <bool kQuick>
void benchStep(benchmark::State& st) {
  odeInit();
  const int n = static_cast<int>(st.range(0));
  auto chain = std::make_unique<OdeChain>(n);
  long k = 0;
  for (auto _ : st) {
    if constexpr (kQuick) {
      dWorldQuickStep(chain->world(), 1e-3);
    } else {
      dWorldStep(chain->world(), 1e-3);
    }
    if (++k % yardsim::bench::kResetSteps == 0) {
      st.PauseTiming();
      chain = std::make_unique<OdeChain>(n);
      st.ResumeTiming();
    }
  }
}

template <bool kQuick>
void benchDrift(benchmark::State& st) {
  odeInit();
  double drift = 0.0;
  for (auto _ : st) {
    OdeChain chain(2);
    // hanging rest energy of the double pendulum: centres at z = -0.5 and -1.5
    const double Emin = -9.81 * (0.5 + 1.5);
    const double E0 = chain.energy() - Emin;
    drift = 0.0;
    for (int k = 0; k < 10000; ++k) {
      if constexpr (kQuick) {
        dWorldQuickStep(chain.world(), 1e-3);
      } else {
        dWorldStep(chain.world(), 1e-3);
      }
      drift = std::max(drift, std::abs(chain.energy() - Emin - E0) / E0);
    }
  }
  st.counters["relative_energy_drift"] = drift;
}

}  // namespace

BENCHMARK(benchStep<false>)->Name("ODEWorldStep")->RangeMultiplier(2)->Range(1, 256);
BENCHMARK(benchStep<true>)->Name("ODEQuickStep")->RangeMultiplier(2)->Range(1, 256);
BENCHMARK(benchDrift<false>)->Name("EnergyDrift/ODEWorldStep")->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(benchDrift<true>)->Name("EnergyDrift/ODEQuickStep")->Iterations(1)->Unit(benchmark::kMillisecond);
