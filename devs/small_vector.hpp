#pragma once
// A growable array of trivially copyable values whose first N elements live inside the object,
// so the common short lists of model construction (a model's ports, a port's couplings) take no
// heap block. The inline elements share their bytes with the heap pointer (a SmallVector of one
// or two pointers is 16 or 24 bytes). Not copyable or movable: it lives inside models, whose
// addresses are stable. Past N elements its block comes from the model arena, as the models'
// (devs/model_arena.hpp: no fresh small pages of the heap per growing list).
#include <cstdint>
#include <cstring>
#include <memory>
#include <span>
#include <type_traits>

#include "devs/model_arena.hpp"

namespace yardsim::devs {

template <class T, std::uint32_t N>
class SmallVector {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_default_constructible_v<T> &&
                N > 0);

 public:
  SmallVector() = default;
  SmallVector(const SmallVector&) = delete;
  SmallVector& operator=(const SmallVector&) = delete;
  ~SmallVector() {
    if (onHeap()) ListAllocator<T>().deallocate(heap_, cap_);
  }

  // (value) => appended; the first heap block is taken past N elements, then doubled
  void push_back(T v) {
    if (size_ == cap_) grow(2 * cap_);
    data()[size_++] = v;
  }
  // (position <= size, value) => inserted there, the later elements moved up by one
  void insert(std::uint32_t at, T v) {
    push_back(v);
    if (at + 1 == size_) return;  // appended: nothing to move
    T* d = data();
    std::memmove(static_cast<void*>(d + at + 1), d + at, (size_ - 1 - at) * sizeof(T));
    d[at] = v;
  }
  // (n) => room for n elements without another allocation
  void reserve(std::uint32_t n) {
    if (n > cap_) grow(n);
  }
  // () => no element, capacity kept
  void clear() { size_ = 0; }

  std::uint32_t size() const { return size_; }
  std::uint32_t capacity() const { return cap_; }
  bool empty() const { return size_ == 0; }
  T* data() { return onHeap() ? heap_ : inline_; }
  const T* data() const { return onHeap() ? heap_ : inline_; }
  T* begin() { return data(); }
  T* end() { return data() + size_; }
  const T* begin() const { return data(); }
  const T* end() const { return data() + size_; }
  T& operator[](std::uint32_t i) { return data()[i]; }
  const T& operator[](std::uint32_t i) const { return data()[i]; }
  std::span<const T> span() const { return {data(), size_}; }

 private:
  bool onHeap() const { return cap_ > N; }
  // (capacity > size) => the elements moved to a heap block of that capacity
  void grow(std::uint32_t cap) {
    T* fresh = ListAllocator<T>().allocate(cap);
    std::memcpy(static_cast<void*>(fresh), data(), size_ * sizeof(T));
    if (onHeap()) ListAllocator<T>().deallocate(heap_, cap_);
    heap_ = fresh;
    cap_ = cap;
  }

  union {
    T inline_[N]{};  // the elements while cap_ == N
    T* heap_;        // the elements once cap_ > N
  };
  std::uint32_t size_ = 0;
  std::uint32_t cap_ = N;
};

}  // namespace yardsim::devs
