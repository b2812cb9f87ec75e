// Box barge RAOs (tests/forces/hydro/td_fixtures.hpp: 6 x 4 m, 1 m draft) in regular beam and head
// seas: measured from time-domain runs of the `rankine_td` provider (regular_wave_run.hpp) and
// from the frequency-domain solve of the same panels (frequency_domain.hpp), as CSV for
// plot_barge_rao.py (docs/hydrodynamics.md).
// Usage: hydro_barge_rao [periods analysis_periods steps_per_period [w ...]] > barge_rao.csv
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <vector>

#include "forces/hydro/frequency_domain.hpp"
#include "forces/hydro/regular_wave_run.hpp"
#include "tests/forces/hydro/td_fixtures.hpp"

using namespace yardsim;
using namespace yardsim::forces::hydro;
using namespace yardsim::forces::hydro::test;

int main(int argc, char** argv) {
  const int periods = argc > 1 ? std::atoi(argv[1]) : 40;
  const int analysis = argc > 2 ? std::atoi(argv[2]) : 10;
  const int perPeriod = argc > 3 ? std::atoi(argv[3]) : 60;
  std::vector<double> omegas;
  for (int i = 4; i < argc; ++i) omegas.push_back(std::atof(argv[i]));
  if (omegas.empty()) omegas = {1.0, 1.25, 1.5, 1.75, 2.0, 2.25, 2.5, 2.75, 3.0};
  std::printf(
      "sea,mode,omega,measured,reference,measured_phase,reference_phase,N_body,N_surface\n");
  const char* names[6] = {"surge", "sway", "heave", "roll", "pitch", "yaw"};
  for (const double omega : omegas) {
    const BoxBarge barge;
    const auto model = std::make_shared<const RankineTdModel>(barge.hull(), dynamics::Transform{},
                                                              BoxBarge::settings(omega));
    const FrequencyDomainSolver solver(*model);
    const double beam = 0.5 * std::numbers::pi, head = std::numbers::pi;
    const FrequencyResponse r = solver.solve(omega, {beam, head});
    for (const int sea : {0, 1}) {
      const std::vector<int> modes =
          sea == 0 ? std::vector<int>{1, 2, 3} : std::vector<int>{0, 2, 4};
      const auto reference =
          responseAmplitude(rigidBodyMass(BoxBarge::body()), BoxBarge::restoring(),
                            BoxBarge::viscousDamping(), r, static_cast<std::size_t>(sea), modes);
      RegularWaveRun run;
      run.omega = omega;
      run.heading = sea == 0 ? beam : head;
      run.amplitude = 0.05;
      run.periods = periods;
      run.analysisPeriods = analysis;
      run.step = 2.0 * std::numbers::pi / omega / perPeriod;
      run.freeModes = modes;
      run.damping = BoxBarge::viscousDamping();
      const auto measured = measuredResponse(model, BoxBarge::body(), BoxBarge::restoring(), run);
      for (const int m : modes)
        std::printf("%s,%s,%.3f,%.5f,%.5f,%.4f,%.4f,%d,%d\n", sea == 0 ? "beam" : "head", names[m],
                    omega, std::abs(measured[m]), std::abs(reference[m]), std::arg(measured[m]),
                    std::arg(reference[m]), model->problem().bodyCount(),
                    model->problem().surfaceCount());
      std::fflush(stdout);
    }
  }
}
