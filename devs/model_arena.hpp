#pragma once
// The memory models live in: slabs of 2 MiB, each aligned to its size, from which a thread takes
// its models' blocks one after the other (a bump pointer: no heap block, no allocator header per
// model, and the models of one build side by side). Where the kernel offers transparent huge
// pages on request, a slab is one huge page: a model's first touch costs no page fault of its
// own. A slab goes back to the system once its thread has moved on to the next one and its last
// block is released (from any thread); blocks are never reused within a slab, which suits
// models: built together, freed together. Blocks above kLargest bytes, and every block in a
// build with AddressSanitizer (which must see each block), come from the global heap.
#include <cstddef>

namespace yardsim::devs {

class ModelArena {
 public:
  static constexpr std::size_t kSlabBytes = std::size_t{2} << 20;
  static constexpr std::size_t kLargest = std::size_t{64} << 10;
  static constexpr std::size_t kAlign = 16;  // __STDCPP_DEFAULT_NEW_ALIGNMENT__ on x86-64

  // (size) => a block of at least size bytes aligned to kAlign; throws std::bad_alloc
  static void* allocate(std::size_t size);
  // (block from allocate, the same size) => released
  static void release(void* block, std::size_t size) noexcept;
  // () => slabs held now, all threads together (tests)
  static std::size_t slabsHeld();
  // () => whether blocks of at most kLargest bytes come from slabs in this build
  static bool usesSlabs();
};

}  // namespace yardsim::devs
