#include "devs/model_arena.hpp"

#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>
#include <memory>
#include <thread>
#include <vector>

#include "devs/coupled.hpp"
#include "support/test_models.hpp"

using yardsim::devs::ModelArena;

namespace {
// (block) => its slab, as the arena finds it
std::uintptr_t slabOf(const void* p) {
  return reinterpret_cast<std::uintptr_t>(p) & ~(ModelArena::kSlabBytes - 1);
}
}  // namespace

TEST_CASE("arena blocks are aligned, apart, and side by side in one slab") {
  std::vector<std::byte*> blocks;
  for (std::size_t size : {1, 24, 296, 17, 304, 1000}) {
    auto* p = static_cast<std::byte*>(ModelArena::allocate(size));
    CHECK(reinterpret_cast<std::uintptr_t>(p) % ModelArena::kAlign == 0);
    std::memset(p, 0xab, size);
    blocks.push_back(p);
  }
  if (ModelArena::usesSlabs()) {
    // (consecutive blocks) => the next one starts where the previous one's rounded size ends,
    // unless the slab was full and the next one opened a new slab
    const std::size_t sizes[] = {16, 32, 304, 32, 304};
    for (std::size_t i = 0; i + 1 < blocks.size(); ++i)
      if (slabOf(blocks[i]) == slabOf(blocks[i + 1]))
        CHECK(blocks[i + 1] - blocks[i] == static_cast<std::ptrdiff_t>(sizes[i]));
  }
  const std::size_t sizes[] = {1, 24, 296, 17, 304, 1000};
  for (std::size_t i = 0; i < blocks.size(); ++i) ModelArena::release(blocks[i], sizes[i]);
}

TEST_CASE("a slab goes back to the system after the thread moved on and its blocks are freed") {
  if (!ModelArena::usesSlabs()) return;
  const std::size_t before = ModelArena::slabsHeld();
  // (blocks filling three slabs) => at least two more slabs held while they live
  constexpr std::size_t size = 4096;
  std::vector<void*> blocks;
  for (std::size_t i = 0; i < 3 * ModelArena::kSlabBytes / size; ++i)
    blocks.push_back(ModelArena::allocate(size));
  CHECK(ModelArena::slabsHeld() >= before + 2);
  CHECK(slabOf(blocks.front()) != slabOf(blocks.back()));
  for (void* p : blocks) ModelArena::release(p, size);
  // the current slab stays with this thread; every slab it left is unmapped
  CHECK(ModelArena::slabsHeld() <= before + 1);
}

TEST_CASE("blocks freed by another thread, and a thread's slab released when it ends") {
  if (!ModelArena::usesSlabs()) return;
  const std::size_t before = ModelArena::slabsHeld();
  std::vector<void*> blocks;
  std::thread maker([&] {
    for (int i = 0; i < 100; ++i) blocks.push_back(ModelArena::allocate(200));
  });
  maker.join();
  CHECK(ModelArena::slabsHeld() == before + 1);  // the ended thread's slab, still in use
  for (void* p : blocks) ModelArena::release(p, 200);
  CHECK(ModelArena::slabsHeld() == before);
}

TEST_CASE("large blocks come from the global heap") {
  void* small = ModelArena::allocate(16);
  const std::size_t before = ModelArena::slabsHeld();
  void* large = ModelArena::allocate(ModelArena::kLargest + 1);
  CHECK(ModelArena::slabsHeld() == before);  // no slab opened for it
  if (ModelArena::usesSlabs()) CHECK(slabOf(large) != slabOf(small));
  ModelArena::release(large, ModelArena::kLargest + 1);
  ModelArena::release(small, 16);
}

TEST_CASE("lists come from the current slab whatever their size up to a slab's") {
  using yardsim::devs::ListVector;
  const std::size_t big = 4 * ModelArena::kLargest;  // the heap's for a model, a slab's for a list
  auto* list = static_cast<std::byte*>(ModelArena::allocateList(big));
  CHECK(reinterpret_cast<std::uintptr_t>(list) % ModelArena::kAlign == 0);
  std::memset(list, 0x5a, big);
  auto* after = static_cast<std::byte*>(ModelArena::allocateList(24));
  if (ModelArena::usesSlabs() && slabOf(after) == slabOf(list)) CHECK(after - list == big);
  ModelArena::releaseList(after, 24);
  ModelArena::releaseList(list, big);
  // (a list sized once) => its elements, from the arena
  ListVector<double> values;
  values.reserve(1000);
  for (int i = 0; i < 1000; ++i) values.push_back(0.5 * i);
  CHECK(values.capacity() == 1000);
  CHECK(values[999] == 499.5);
}

TEST_CASE("lists come from slabs apart from the models', which stay side by side") {
  if (!ModelArena::usesSlabs()) return;
  auto* a = static_cast<std::byte*>(ModelArena::allocate(304));
  void* list = ModelArena::allocateList(2048);  // a list grown between two models
  auto* b = static_cast<std::byte*>(ModelArena::allocate(304));
  CHECK(slabOf(list) != slabOf(a));
  if (slabOf(a) == slabOf(b)) CHECK(b - a == 304);
  ModelArena::release(b, 304);
  ModelArena::releaseList(list, 2048);
  ModelArena::release(a, 304);
}

TEST_CASE("a list larger than a slab has its own mapping, returned when released") {
  const std::size_t before = ModelArena::slabsHeld();
  const std::size_t size = ModelArena::kSlabBytes + 4096;
  auto* list = static_cast<std::byte*>(ModelArena::allocateList(size));
  if (ModelArena::usesSlabs())
    CHECK(reinterpret_cast<std::uintptr_t>(list) % ModelArena::kSlabBytes == 0);
  std::memset(list, 0x11, size);  // every byte is there
  CHECK(list[size - 1] == std::byte{0x11});
  CHECK(ModelArena::slabsHeld() == before);  // not a slab: no other block shares it
  ModelArena::releaseList(list, size);
  CHECK(ModelArena::slabsHeld() == before);
}

TEST_CASE("models are built in the arena and freed with it") {
  if (!ModelArena::usesSlabs()) return;
  auto root = std::make_unique<yardsim::devs::Coupled>("root");
  auto& a = root->add<yardsim::testing::Emitter>("a", std::vector<yardsim::devs::Time>{1.0});
  auto& b = root->add<yardsim::testing::Emitter>("b", std::vector<yardsim::devs::Time>{2.0});
  // (two models added one after the other) => in one slab, b right after a
  CHECK(slabOf(&a) == slabOf(&b));
  CHECK(reinterpret_cast<std::byte*>(&b) - reinterpret_cast<std::byte*>(&a) ==
        static_cast<std::ptrdiff_t>((sizeof(a) + 15) / 16 * 16));
  root.reset();  // every model released, no crash
}
