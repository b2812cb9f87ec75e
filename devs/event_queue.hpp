#pragma once
// Indexed binary min-heap of next-event times: O(log n) to schedule, move or remove one model.
// Passive models (tn = infinity) are kept out of the heap. Its lists are sized once (resize), in
// the model arena's list slabs (apart from the models, devs/model_arena.hpp); the heap is a
// prefix of its list, so an insert or removal never reaches an allocator's growth path.
#include <cstdint>
#include <vector>

#include "devs/checkpoint_archive.hpp"
#include "devs/model_arena.hpp"
#include "devs/time.hpp"

namespace yardsim::devs {

class EventQueue {
 public:
  explicit EventQueue(std::size_t models = 0) { resize(models); }
  void resize(std::size_t models);

  bool empty() const { return size_ == 0; }
  Time topTime() const { return empty() ? kInfinity : tn_[heap_[0]]; }
  // () => index of a model with the smallest tn, removed from the heap
  std::uint32_t pop();
  // (model, tn) => scheduled at tn (inserted, moved, or removed when tn is infinite)
  void schedule(std::uint32_t model, Time tn);
  Time tn(std::uint32_t model) const { return tn_[model]; }
  // (archive) => the heap exactly as it is (ties pop in the same order after a restore)
  void save(CheckpointWriter& w) const;
  // (archive of a queue over as many models) => that heap; CheckpointError when it is not one
  void load(CheckpointReader& r);

 private:
  static constexpr std::uint32_t kAbsent = 0xffffffffu;
  void siftUp(std::uint32_t pos);
  void siftDown(std::uint32_t pos);
  void removeAt(std::uint32_t pos);

  ListVector<std::uint32_t> heap_;  // model indices: the heap is heap_[0, size_)
  std::uint32_t size_ = 0;
  ListVector<std::uint32_t> pos_;   // heap position of each model, or kAbsent
  ListVector<Time> tn_;             // next event time of each model
};

}  // namespace yardsim::devs
