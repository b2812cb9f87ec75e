#include "devs/event_queue.hpp"

namespace yardsim::devs {

void EventQueue::resize(std::size_t models) {
  heap_.assign(models, 0);
  size_ = 0;
  pos_.assign(models, kAbsent);
  tn_.assign(models, kInfinity);
}

// (entry at pos) => moved up to its place; inlined into its callers (one call fewer per pop and
// schedule, whose frames hold it already)
[[gnu::always_inline]] inline void EventQueue::siftUp(std::uint32_t pos) {
  const std::uint32_t m = heap_[pos];
  const Time t = tn_[m];
  while (pos > 0) {
    const std::uint32_t parent = (pos - 1) / 2;
    if (!(t < tn_[heap_[parent]])) break;
    heap_[pos] = heap_[parent];
    pos_[heap_[pos]] = pos;
    pos = parent;
  }
  heap_[pos] = m;
  pos_[m] = pos;
}

// (entry at pos) => moved down to its place
[[gnu::always_inline]] inline void EventQueue::siftDown(std::uint32_t pos) {
  const std::uint32_t n = size_;
  const std::uint32_t m = heap_[pos];
  const Time t = tn_[m];
  for (;;) {
    std::uint32_t child = 2 * pos + 1;
    if (child >= n) break;
    if (child + 1 < n && tn_[heap_[child + 1]] < tn_[heap_[child]]) ++child;
    if (!(tn_[heap_[child]] < t)) break;
    heap_[pos] = heap_[child];
    pos_[heap_[pos]] = pos;
    pos = child;
  }
  heap_[pos] = m;
  pos_[m] = pos;
}

std::uint32_t EventQueue::pop() {
  // (heap) => its root removed: the last entry sifted down from the root (removeAt's siftUp
  // would not move it there)
  const std::uint32_t top = heap_[0];
  pos_[top] = kAbsent;
  tn_[top] = kInfinity;
  const std::uint32_t last = heap_[--size_];
  if (size_ > 0) {
    heap_[0] = last;
    pos_[last] = 0;
    siftDown(0);
  }
  return top;
}

void EventQueue::schedule(std::uint32_t model, Time tn) {
  const Time old = tn_[model];
  tn_[model] = tn;
  const std::uint32_t p = pos_[model];
  if (tn == kInfinity) {
    if (p != kAbsent) removeAt(p);
    return;
  }
  if (p == kAbsent) {
    pos_[model] = size_;
    heap_[size_] = model;
    siftUp(size_++);
  } else if (tn < old) {
    siftUp(p);
  } else if (tn > old) {
    siftDown(p);
  }
}

void EventQueue::removeAt(std::uint32_t pos) {
  const std::uint32_t gone = heap_[pos];
  pos_[gone] = kAbsent;
  const std::uint32_t last = heap_[--size_];
  if (pos == size_) return;
  heap_[pos] = last;
  pos_[last] = pos;
  siftDown(pos);
  siftUp(pos_[last]);
}

void EventQueue::save(CheckpointWriter& w) const {
  w.section("event_queue");
  devs::save(w, ListVector<std::uint32_t>(heap_.begin(), heap_.begin() + size_));
  devs::save(w, tn_);
}

void EventQueue::load(CheckpointReader& r) {
  r.section("event_queue");
  ListVector<std::uint32_t> heap;
  ListVector<Time> tn;
  devs::load(r, heap);
  devs::load(r, tn);
  if (tn.size() != tn_.size())
    throw CheckpointError("the checkpoint's event queue has " + std::to_string(tn.size()) +
                          " models, this scene " + std::to_string(tn_.size()));
  // (heap, times) => positions rebuilt; every entry a model, once, with a finite time
  ListVector<std::uint32_t> pos(tn.size(), kAbsent);
  for (std::size_t k = 0; k < heap.size(); ++k) {
    if (heap[k] >= tn.size() || pos[heap[k]] != kAbsent || tn[heap[k]] == kInfinity)
      throw CheckpointError("the checkpoint's event queue is inconsistent at entry " +
                            std::to_string(k));
    pos[heap[k]] = static_cast<std::uint32_t>(k);
  }
  size_ = static_cast<std::uint32_t>(heap.size());
  heap.resize(tn.size());  // the heap as a prefix of a list with room for every model
  heap_ = std::move(heap);
  tn_ = std::move(tn);
  pos_ = std::move(pos);
}

}  // namespace yardsim::devs
