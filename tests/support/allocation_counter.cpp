#include "support/allocation_counter.hpp"

#include "support/malloc_counter.hpp"

// (every operator new of the standard library takes its memory from malloc or the aligned
// allocators, which malloc_counter.cpp counts; so do Eigen and the C libraries) => one count
std::size_t yardsim::testing::allocationCount() {
  return mallocCount();
}
