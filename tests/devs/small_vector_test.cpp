#include "devs/small_vector.hpp"

#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdint>

using yardsim::devs::SmallVector;

TEST_CASE("a small vector keeps every element across its move to the heap") {
  SmallVector<std::uint64_t, 2> v;
  CHECK(v.empty());
  const std::uint64_t* inlineData = v.data();
  for (std::uint64_t i = 0; i < 1000; ++i) {
    v.push_back(i * i + 7);
    if (i < 2) CHECK(v.data() == inlineData);  // the first two live in the object
  }
  CHECK(v.data() != inlineData);
  REQUIRE(v.size() == 1000);
  std::uint64_t sum = 0;
  for (std::uint64_t x : v) sum += x;
  CHECK(sum == 332833500 + 7000);  // sum of i^2 for i < 1000, plus 7 each
  CHECK(v.span().size() == 1000);
  CHECK(v[999] == 999 * 999 + 7);
}

TEST_CASE("reserve keeps the elements and takes no block while they fit") {
  SmallVector<int, 4> v;
  v.push_back(1);
  v.reserve(3);
  const int* before = v.data();
  v.push_back(2);
  v.push_back(3);
  CHECK(v.data() == before);
  v.reserve(100);
  const int* grown = v.data();
  for (int i = 4; i <= 100; ++i) v.push_back(i);
  CHECK(v.data() == grown);
  for (int i = 0; i < 100; ++i) CHECK(v[static_cast<std::uint32_t>(i)] == i + 1);
}

TEST_CASE(
    "the inline elements share their bytes with the heap pointer, and clear keeps the block") {
  CHECK(sizeof(SmallVector<void*, 1>) == 16);
  CHECK(sizeof(SmallVector<void*, 2>) == 24);
  SmallVector<int, 2> v;
  v.push_back(1);
  v.push_back(2);
  CHECK(v.capacity() == 2);
  v.push_back(3);  // moved to a block of 4
  CHECK(v.capacity() == 4);
  const int* block = v.data();
  v.clear();
  CHECK(v.empty());
  for (int i = 0; i < 4; ++i) v.push_back(10 + i);
  CHECK(v.data() == block);
  v.insert(0, 9);
  REQUIRE(v.size() == 5);
  for (std::uint32_t i = 0; i < 5; ++i) CHECK(v[i] == static_cast<int>(9 + i));
}

TEST_CASE("insert at the end appends, in the middle moves the later elements up") {
  SmallVector<int, 2> v;
  v.insert(0, 1);  // at the end of an empty list
  v.insert(1, 3);  // at the end
  v.insert(1, 2);  // in the middle, past the inline capacity
  v.insert(3, 4);  // at the end again
  v.insert(0, 0);  // at the front
  REQUIRE(v.size() == 5);
  for (std::uint32_t i = 0; i < 5; ++i) CHECK(v[i] == static_cast<int>(i));
}

TEST_CASE("a grown small vector's block comes from the model arena") {
  if (!yardsim::devs::ModelArena::usesSlabs()) return;
  SmallVector<std::uint64_t, 1> v;
  for (std::uint64_t i = 0; i < 3; ++i) v.push_back(i);
  // (a block of 4 from the arena's lists, then another list right after it) => side by side
  void* next = yardsim::devs::ModelArena::allocateList(16);
  const auto slab = [](const void* p) {
    return reinterpret_cast<std::uintptr_t>(p) & ~(yardsim::devs::ModelArena::kSlabBytes - 1);
  };
  if (slab(next) == slab(v.data()))
    CHECK(reinterpret_cast<std::byte*>(next) - reinterpret_cast<std::byte*>(v.data()) == 32);
  yardsim::devs::ModelArena::releaseList(next, 16);
}
