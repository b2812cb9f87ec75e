#pragma once
// Test support: every heap allocation of the test executable is counted: operator new, and the
// malloc that Eigen's dynamic-size temporaries and the C libraries (SUNDIALS, FCL) call past it.
// Link tests/support/allocation_counter.cpp and tests/support/malloc_counter.cpp (glibc only)
// into it. The sanitizers forbid replacing the allocators, so such tests run in the plain build
// only.
#include <cstddef>

namespace yardsim::testing {

// () => how many heap blocks any allocator has handed out so far
std::size_t allocationCount();

}  // namespace yardsim::testing
