#pragma once
// Test support: every call of malloc, calloc, realloc and the aligned allocators in the process is
// counted (link tests/support/malloc_counter.cpp into the test executable; glibc only). Eigen's
// temporaries (dynamic-size products, inverses) call malloc directly, past a counted operator new.
#include <cstddef>

namespace yardsim::testing {

// () => how many times the C allocator has handed out memory so far
std::size_t mallocCount();

}  // namespace yardsim::testing
