#pragma once
// Test support: every global operator new of the test executable is counted (link
// tests/support/allocation_counter.cpp into it). The sanitizers forbid replacing operator new,
// so such tests run in the plain build only.
#include <cstddef>

namespace yardsim::testing {

// () => how many times any global operator new has run so far
std::size_t allocationCount();

}  // namespace yardsim::testing
