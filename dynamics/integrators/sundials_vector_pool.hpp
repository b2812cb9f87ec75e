#pragma once
// Serial N_Vectors for CVODE and ARKODE whose empty clones come from a pool made at set-up, so
// that SUNDIALS' own dense difference-quotient Jacobian (cvLsDenseDQJac in cvode_ls.c,
// arkLsDenseDQJac in arkode_ls.c, SUNDIALS 6.4), which takes an empty clone of a work vector for
// the column it writes (N_VCloneEmpty) and destroys it (N_VDestroy) at every Jacobian, allocates
// nothing: its arithmetic is untouched, so every result is the same double.
//
// Each N_Vector carries its own operations table, copied into its clones (N_VCopyOps). The
// vectors made here are the serial implementation's (nvector_serial.h: NV_DATA_S,
// N_VGetArrayPointer and every arithmetic operation work on them) with three operations replaced:
// - nvcloneempty: a free vector of the pool (no data, own_data false), else a new one;
// - nvdestroy: the pool's vectors go back to it, any other is freed as the serial one is;
// - nvclone: as the serial one (a new vector owning `length` doubles), with the pool's content, so
//   that clones of clones (CVODE's and ARKODE's work vectors, their Newton solver's) keep the pool.
// Their content is the serial one (length, own_data, data) followed by the pool and whether the
// vector is one of its own. Every such vector must be destroyed before the pool; the pool frees
// its own vectors (one still out then is let go: its N_VDestroy frees it).
#include <cstddef>
#include <vector>

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

namespace yardsim::dynamics {

class SundialsVectorPool {
 public:
  /// (context, the vectors' length, how many empty clones may be out at once without allocating)
  /// => the pool, its vectors made (SUNDIALS' Jacobians take one at a time)
  SundialsVectorPool(SUNContext ctx, sunindextype length, int capacity = 2);
  ~SundialsVectorPool();
  SundialsVectorPool(const SundialsVectorPool&) = delete;
  SundialsVectorPool& operator=(const SundialsVectorPool&) = delete;

  /// () => a new serial vector of the pool's length owning its zeroed data, whose clones and empty
  /// clones use the pool; N_VDestroy frees it (before the pool)
  N_Vector makeVector();

  /// How many empty clones were served from the pool, and how many had to be allocated
  /// (the pool's vectors all out) since it was made.
  std::size_t served() const { return served_; }
  std::size_t allocated() const { return allocated_; }

  /// (an empty clone to take) => a free vector of the pool, or nullptr when all are out
  N_Vector take();
  /// (one of the pool's vectors) => it is free again, its data pointer cleared
  void give(N_Vector v);
  /// (a clone served as allocated) => counted
  void countAllocated() { ++allocated_; }

 private:
  SUNContext ctx_;
  sunindextype length_;
  std::vector<N_Vector> own_;   // the pool's vectors, made at construction
  std::vector<N_Vector> free_;  // those not out (its capacity reserved: give() never allocates)
  std::size_t served_ = 0, allocated_ = 0;
};

}  // namespace yardsim::dynamics
