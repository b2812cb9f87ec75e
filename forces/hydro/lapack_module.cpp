// The module libyardsim_lapack.so (forces/hydro/lapack_module.hpp): OpenBLAS's routines by address.
#include "forces/hydro/lapack_module.hpp"

extern "C" {
void dgetrf_(const int* m, const int* n, double* a, const int* lda, int* ipiv, int* info);
void dlaswp_(const int* n, double* a, const int* lda, const int* k1, const int* k2, const int* ipiv,
             const int* incx);
void dtrsm_(const char* side, const char* uplo, const char* transa, const char* diag, const int* m,
            const int* n, const double* alpha, const double* a, const int* lda, double* b,
            const int* ldb);
void dgeev_(const char* jobvl, const char* jobvr, const int* n, double* a, const int* lda,
            double* wr, double* wi, double* vl, const int* ldvl, double* vr, const int* ldvr,
            double* work, const int* lwork, int* info);
}

// () => the library's four routines
extern "C" const yardsim::forces::hydro::LapackRoutines* yardsim_lapack_routines() {
  static const yardsim::forces::hydro::LapackRoutines routines{&dgetrf_, &dlaswp_, &dtrsm_,
                                                               &dgeev_};
  return &routines;
}
