#pragma once
// OpenBLAS's LAPACK and BLAS live behind a module, libyardsim_lapack.so, installed beside
// libyardsim_forces.so and opened (dlopen) the first time a dense solve or eigenvalue problem
// needs them (the time-domain Rankine solver's mixed problem and growth check), so a run without
// one never loads OpenBLAS and libgfortran (about 2 ms of start-up, and OpenBLAS starts its
// thread pool when loaded; docs/performance.md). This header is the seam: the four routines
// (Fortran calling convention), the module's one entry and the loader. No units.
#include <string>

namespace yardsim::forces::hydro {

// The LAPACK and BLAS routines dense_solve.cpp and dense_eigenvalues.cpp call, as in LAPACK:
// P A = L U (DGETRF), row interchanges (DLASWP), triangular solves (DTRSM), eigenvalues (DGEEV)
struct LapackRoutines {
  void (*dgetrf)(const int* m, const int* n, double* a, const int* lda, int* ipiv, int* info);
  void (*dlaswp)(const int* n, double* a, const int* lda, const int* k1, const int* k2,
                 const int* ipiv, const int* incx);
  void (*dtrsm)(const char* side, const char* uplo, const char* transa, const char* diag,
                const int* m, const int* n, const double* alpha, const double* a, const int* lda,
                double* b, const int* ldb);
  void (*dgeev)(const char* jobvl, const char* jobvr, const int* n, double* a, const int* lda,
                double* wr, double* wi, double* vl, const int* ldvl, double* vr, const int* ldvr,
                double* work, const int* lwork, int* info);
};

// () => the module this build loads: libyardsim_lapack.so in the folder libyardsim_forces.so was
// loaded from (build tree and install tree alike); empty in a static build (linked in)
std::string lapackModulePath();

// (module file) => its routines (entry `yardsim_lapack_routines`), the module kept loaded for the
// process. Throws std::runtime_error naming the file and why (missing, not loadable, no entry).
const LapackRoutines& loadLapackModule(const std::string& file);

// () => the routines, the module opened by the first call of the process (a failure is thrown
// again at the next call)
const LapackRoutines& lapack();

}  // namespace yardsim::forces::hydro

// () => the routines, defined by lapack_module.cpp (linked to OpenBLAS)
extern "C" const yardsim::forces::hydro::LapackRoutines* yardsim_lapack_routines();
