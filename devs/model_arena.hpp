#pragma once
// The memory models live in: slabs of 2 MiB, each aligned to its size, from which a thread takes
// its models' blocks one after the other (a bump pointer: no heap block, no allocator header per
// model, and the models of one build side by side). Where the kernel offers transparent huge
// pages on request, a slab is one huge page: a model's first touch costs no page fault of its
// own. A slab goes back to the system once its thread has moved on to the next one and its last
// block is released (from any thread); blocks are never reused within a slab, which suits
// models: built together, freed together. Blocks above kLargest bytes, and every block in a
// build with AddressSanitizer (which must see each block), come from the global heap.
//
// Lists that go with the models (components, couplings, the flat model's, the Simulator's) come
// from slabs too, each thread's lists from a slab of their own beside its models' (allocateList,
// any size up to a slab's; the models stay side by side). A list larger than a slab gets its own
// mapping of whole slabs, advised the same way.
#include <cstddef>
#include <vector>

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
  // (size) => a block for a list of at least size bytes aligned to kAlign, from the current slab
  // when it fits in one (else from a fresh slab, or its own mapping past a slab); std::bad_alloc
  static void* allocateList(std::size_t size);
  // (block from allocateList, the same size) => released
  static void releaseList(void* block, std::size_t size) noexcept;
  // () => slabs held now, all threads together (tests)
  static std::size_t slabsHeld();
  // () => whether blocks of at most kLargest bytes come from slabs in this build
  static bool usesSlabs();
};

// An allocator for lists sized once (reserve or assign to their final size, then no growth):
// their blocks come from ModelArena::allocateList.
template <class T>
struct ListAllocator {
  static_assert(alignof(T) <= ModelArena::kAlign);
  using value_type = T;
  ListAllocator() = default;
  template <class U>
  ListAllocator(const ListAllocator<U>&) noexcept {}  // NOLINT: converting, as allocators are
  T* allocate(std::size_t n) { return static_cast<T*>(ModelArena::allocateList(n * sizeof(T))); }
  void deallocate(T* p, std::size_t n) noexcept { ModelArena::releaseList(p, n * sizeof(T)); }
  friend bool operator==(ListAllocator, ListAllocator) { return true; }
};
template <class T>
using ListVector = std::vector<T, ListAllocator<T>>;

}  // namespace yardsim::devs
