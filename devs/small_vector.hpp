#pragma once
// A growable array of trivially copyable values whose first N elements live inside the object,
// so the common short lists of model construction (a model's ports, a port's couplings) take no
// heap block. Not copyable or movable: it lives inside models, whose addresses are stable.
#include <cstdint>
#include <cstring>
#include <memory>
#include <span>
#include <type_traits>

namespace yardsim::devs {

template <class T, std::uint32_t N>
class SmallVector {
  static_assert(std::is_trivially_copyable_v<T> && N > 0);

 public:
  SmallVector() = default;
  SmallVector(const SmallVector&) = delete;
  SmallVector& operator=(const SmallVector&) = delete;
  ~SmallVector() {
    if (data_ != inline_) std::allocator<T>().deallocate(data_, cap_);
  }

  // (value) => appended; the first heap block is taken past N elements, then doubled
  void push_back(T v) {
    if (size_ == cap_) grow(2 * cap_);
    data_[size_++] = v;
  }
  // (position <= size, value) => inserted there, the later elements moved up by one
  void insert(std::uint32_t at, T v) {
    push_back(v);
    std::memmove(static_cast<void*>(data_ + at + 1), data_ + at, (size_ - 1 - at) * sizeof(T));
    data_[at] = v;
  }
  // (n) => room for n elements without another allocation
  void reserve(std::uint32_t n) {
    if (n > cap_) grow(n);
  }

  std::uint32_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T* data() { return data_; }
  const T* data() const { return data_; }
  T* begin() { return data_; }
  T* end() { return data_ + size_; }
  const T* begin() const { return data_; }
  const T* end() const { return data_ + size_; }
  T& operator[](std::uint32_t i) { return data_[i]; }
  const T& operator[](std::uint32_t i) const { return data_[i]; }
  std::span<const T> span() const { return {data_, size_}; }

 private:
  // (capacity > size) => the elements moved to a heap block of that capacity
  void grow(std::uint32_t cap) {
    T* fresh = std::allocator<T>().allocate(cap);
    std::memcpy(static_cast<void*>(fresh), data_, size_ * sizeof(T));
    if (data_ != inline_) std::allocator<T>().deallocate(data_, cap_);
    data_ = fresh;
    cap_ = cap;
  }

  T* data_ = inline_;
  std::uint32_t size_ = 0;
  std::uint32_t cap_ = N;
  T inline_[N]{};
};

}  // namespace yardsim::devs
