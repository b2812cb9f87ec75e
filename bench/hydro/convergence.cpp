// The convergence study of docs/hydrodynamics.md: relative error of the sphere's surge added mass
// (unbounded fluid, 0.5 rho V) and of the floating hemisphere's heave added mass (infinite
// frequency, 0.5 rho (2/3) pi a^3) on equiangular cube spheres of 6 n^2 panels (hemisphere:
// 3 n^2), n = 4 ... 32. Prints CSV: mesh,n,panels,error_percent.
// Run: hydro_convergence > convergence.csv; python3 bench/hydro/plot_convergence.py convergence.csv
#include <cstdio>
#include <numbers>

#include "forces/hydro/added_mass.hpp"
#include "forces/hydro/hull_shapes.hpp"
#include "forces/hydro/wetted_surface.hpp"

using namespace yardsim::forces::hydro;

int main() {
  const double pi = std::numbers::pi;
  std::printf("mesh,n,panels,error_percent\n");
  for (const int n : {4, 8, 12, 16, 24, 32}) {
    const PanelMesh sphere = cubeSphere(1.0, n);
    AddedMassOptions o;
    o.rho = 1.0;
    const Matrix6 A = addedMass(sphere, o);
    std::printf("sphere,%d,%d,%.6f\n", n, sphere.panelCount(), 100.0 * (A(0, 0) / (2.0 / 3.0 * pi) - 1.0));
    const PanelMesh wet = wettedSurface(sphere);
    o.solver.freeSurface = FreeSurface::NegativeImage;
    const Matrix6 H = addedMass(wet, o);
    std::printf("hemisphere,%d,%d,%.6f\n", n, wet.panelCount(), 100.0 * (H(2, 2) / (pi / 3.0) - 1.0));
    std::fflush(stdout);
  }
}
