#include "support/malloc_counter.hpp"

#include <cerrno>
#include <cstddef>

// glibc's own allocator under its internal names: the definitions below replace the public ones
// for the whole process (glibc supports replacing malloc this way) and forward to these
extern "C" {
void* __libc_malloc(std::size_t n);
void* __libc_calloc(std::size_t n, std::size_t size);
void* __libc_realloc(void* p, std::size_t n);
void* __libc_memalign(std::size_t alignment, std::size_t n);
void __libc_free(void* p);
}

namespace {
std::size_t gMallocs = 0;
}

std::size_t yardsim::testing::mallocCount() { return gMallocs; }

// (size) => memory, counted
extern "C" void* malloc(std::size_t n) {
  ++gMallocs;
  return __libc_malloc(n);
}
extern "C" void* calloc(std::size_t n, std::size_t size) {
  ++gMallocs;
  return __libc_calloc(n, size);
}
extern "C" void* realloc(void* p, std::size_t n) {
  ++gMallocs;
  return __libc_realloc(p, n);
}
extern "C" void* memalign(std::size_t alignment, std::size_t n) {
  ++gMallocs;
  return __libc_memalign(alignment, n);
}
extern "C" void* aligned_alloc(std::size_t alignment, std::size_t n) {
  ++gMallocs;
  return __libc_memalign(alignment, n);
}
extern "C" int posix_memalign(void** out, std::size_t alignment, std::size_t n) {
  ++gMallocs;
  void* p = __libc_memalign(alignment, n);
  if (p == nullptr) return ENOMEM;
  *out = p;
  return 0;
}
extern "C" void free(void* p) { __libc_free(p); }
