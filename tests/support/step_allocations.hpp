#pragma once
// Test support: what the steps of an integrator may allocate once set up. Nothing, except in
// SUNDIALS' own difference-quotient Jacobian of the implicit CVODE and ARKODE methods
// (cvLsDenseDQJac and arkLsDenseDQJac, SUNDIALS 6.4), which clones an N_Vector at every Jacobian
// evaluation (N_VCloneEmpty: the vector, its operations and its content, three heap blocks) and
// frees it at its end. Count with support/allocation_counter.hpp.
#include <catch2/catch.hpp>
#include <cstddef>

#include "dynamics/integrators/factory.hpp"

namespace yardsim::testing {

inline constexpr std::size_t kSundialsJacobianBlocks = 3;

// (method, the heap blocks its steps allocated, how many steps) => checked: none, or for SUNDIALS'
// implicit methods whole Jacobians' clones only, at most one Jacobian a step
inline void checkStepAllocations(const dynamics::MethodInfo& method, std::size_t blocks,
                                 int steps) {
  INFO(method.name << ": " << blocks << " heap blocks in " << steps << " steps");
  if (!(method.adaptive && method.implicit)) {
    CHECK(blocks == 0);
    return;
  }
  CHECK(blocks % kSundialsJacobianBlocks == 0);
  CHECK(blocks <= kSundialsJacobianBlocks * static_cast<std::size_t>(steps));
}

}  // namespace yardsim::testing
