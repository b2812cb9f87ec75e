#include "devs/model_arena.hpp"

#include <sys/mman.h>

#include <atomic>
#include <cstdint>
#include <new>

namespace yardsim::devs {
namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSlabs = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kSlabs = false;
#else
constexpr bool kSlabs = true;
#endif
#else
constexpr bool kSlabs = true;
#endif

// A slab's first bytes. balance = blocks credited by the owning thread when it moved on, minus
// blocks released: it reaches 0 exactly once, after the move and the last release, in whichever
// of the two comes last, and that one unmaps the slab. While the slab is current the owner
// counts its blocks in a plain integer (no atomic operation per model).
struct alignas(ModelArena::kAlign) Slab {
  std::atomic<std::int64_t> balance{0};
};
constexpr std::size_t kHeader = (sizeof(Slab) + ModelArena::kAlign - 1) & ~(ModelArena::kAlign - 1);

std::atomic<std::size_t> heldSlabs{0};

// (bytes, a multiple of kSlabBytes) => a fresh mapping aligned to kSlabBytes, advised as huge
// pages
void* mapAligned(std::size_t bytes) {
  constexpr std::size_t n = ModelArena::kSlabBytes;
  void* raw = mmap(nullptr, bytes + n, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  // (bytes + n) => the n-aligned bytes inside kept, the rest unmapped
  const auto at = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t start = (at + n - 1) & ~(n - 1);
  if (start > at) munmap(raw, start - at);
  if (start + bytes < at + bytes + n)
    munmap(reinterpret_cast<void*>(start + bytes), at + n - start);
  void* block = reinterpret_cast<void*>(start);
#ifdef MADV_HUGEPAGE
  madvise(block, bytes, MADV_HUGEPAGE);
#endif
  return block;
}

// () => a fresh slab aligned to its size, one huge page where the kernel grants it
Slab* mapSlab() {
  void* slab = mapAligned(ModelArena::kSlabBytes);
  heldSlabs.fetch_add(1, std::memory_order_relaxed);
  return ::new (slab) Slab;
}

void unmapSlab(Slab* slab) {
  slab->~Slab();
  munmap(slab, ModelArena::kSlabBytes);
  heldSlabs.fetch_sub(1, std::memory_order_relaxed);
}

// (slab, blocks it handed out) => the owner's credit; unmapped when they are all released
void retire(Slab* slab, std::int64_t blocks) {
  if (slab->balance.fetch_add(blocks, std::memory_order_acq_rel) + blocks == 0) unmapSlab(slab);
}

// The calling thread's current slab.
struct Current {
  Slab* slab = nullptr;
  std::size_t used = 0;     // bytes taken, header included
  std::int64_t blocks = 0;  // blocks handed out
  ~Current() {
    if (slab) retire(slab, blocks);
    slab = nullptr;
  }
};
// initial-exec: the library is linked, not opened with dlopen, so the slab is found without a
// call to __tls_get_addr per model
// Two per thread: the models' and the lists' (apart, so that the models of one build stay side by
// side: a list that grows leaves its old blocks behind, which would spread the models out).
[[gnu::tls_model("initial-exec")]] thread_local Current current;
[[gnu::tls_model("initial-exec")]] thread_local Current currentLists;

// (current slab of this thread, size rounded to kAlign, at most a slab's room) => a block from it
void* fromSlab(Current& c, std::size_t size) {
  constexpr std::size_t kSlabBytes = ModelArena::kSlabBytes;
  if (!c.slab || c.used + size > kSlabBytes) {
    Slab* fresh = mapSlab();
    if (c.slab) retire(c.slab, c.blocks);
    c.slab = fresh;
    c.used = kHeader;
    c.blocks = 0;
  }
  void* block = reinterpret_cast<std::byte*>(c.slab) + c.used;
  c.used += size;
  ++c.blocks;
  return block;
}

// (block in a slab) => released; the slab unmapped with its last block once its owner moved on
void toSlab(void* block) noexcept {
  auto* slab = reinterpret_cast<Slab*>(reinterpret_cast<std::uintptr_t>(block) &
                                       ~(ModelArena::kSlabBytes - 1));
  if (slab->balance.fetch_sub(1, std::memory_order_acq_rel) == 1) unmapSlab(slab);
}

constexpr std::size_t kSlabRoom = ModelArena::kSlabBytes - kHeader;
// (list bytes past a slab's room) => the bytes of its own mapping, whole slabs
constexpr std::size_t ownMapping(std::size_t size) {
  return (size + ModelArena::kSlabBytes - 1) & ~(ModelArena::kSlabBytes - 1);
}

}  // namespace

void* ModelArena::allocate(std::size_t size) {
  size = (size + kAlign - 1) & ~(kAlign - 1);
  if (!kSlabs || size > kLargest) return ::operator new(size);
  return fromSlab(current, size);
}

void ModelArena::release(void* block, std::size_t size) noexcept {
  if (!block) return;
  size = (size + kAlign - 1) & ~(kAlign - 1);
  if (!kSlabs || size > kLargest) {
    ::operator delete(block);  // unsized: clang has no sized deallocation by default
    return;
  }
  toSlab(block);
}

void* ModelArena::allocateList(std::size_t size) {
  size = (size + kAlign - 1) & ~(kAlign - 1);
  if (!kSlabs) return ::operator new(size);
  if (size <= kSlabRoom) return fromSlab(currentLists, size);
  return mapAligned(ownMapping(size));
}

void ModelArena::releaseList(void* block, std::size_t size) noexcept {
  if (!block) return;
  size = (size + kAlign - 1) & ~(kAlign - 1);
  if (!kSlabs) {
    ::operator delete(block);  // unsized: clang has no sized deallocation by default
    return;
  }
  if (size <= kSlabRoom)
    toSlab(block);
  else
    munmap(block, ownMapping(size));
}

std::size_t ModelArena::slabsHeld() {
  return heldSlabs.load(std::memory_order_relaxed);
}

bool ModelArena::usesSlabs() {
  return kSlabs;
}

}  // namespace yardsim::devs
