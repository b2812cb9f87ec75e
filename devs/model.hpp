#pragma once
// Common base of atomic and coupled models: a name, a parent, typed input and output ports.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "devs/port.hpp"
#include "devs/small_vector.hpp"

namespace yardsim::devs {

// A structural mistake in a model (bad name, bad coupling): thrown at construction time.
class ModelError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Model {
 public:
  explicit Model(std::string name);
  virtual ~Model();
  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;

  // Models live in slabs (devs/model_arena.hpp): (size) => a block for a model of that size;
  // (block, the same size) => freed. Over-aligned model types go to the global heap.
  static void* operator new(std::size_t size);
  static void operator delete(void* block, std::size_t size) noexcept;
  static void* operator new(std::size_t size, std::align_val_t align) {
    return ::operator new(size, align);
  }
  static void operator delete(void* block, std::size_t, std::align_val_t align) noexcept {
    ::operator delete(block, align);  // unsized: clang has no sized deallocation by default
  }
  static void* operator new(std::size_t, void* at) noexcept { return at; }
  static void operator delete(void*, void*) noexcept {}

  const std::string& name() const { return name_; }
  // () => full dot-separated path from the root, e.g. "gpt.ef.genr" (cached); a root whose
  // name is hidden (a scene) does not appear in its descendants' paths: "ef.genr"
  const std::string& path() const;
  // () => this model's name left out of its descendants' paths (call before adding children)
  void hideNameInPaths() {
    hidden_ = true;
    treeChanged();
  }
  Coupled* parent() const { return parent_; }
  virtual bool isAtomic() const = 0;

  // Ports in the order they were added; owned by this model, valid as long as it lives.
  std::span<PortBase* const> inPorts() const { return {ports_.data(), nIn_}; }
  std::span<PortBase* const> outPorts() const {
    return {ports_.data() + nIn_, ports_.size() - nIn_};
  }
  // (name) => input or output port of that name, or nullptr
  PortBase* findPort(std::string_view name) const;

  template <class T>
  InPort<T>& addInPort(std::string name) {
    auto& p = addPort<InPort<T>>(std::move(name), nIn_);
    ++nIn_;
    return p;
  }
  template <class T>
  OutPort<T>& addOutPort(std::string name) {
    return addPort<OutPort<T>>(std::move(name), ports_.size());
  }

 private:
  friend class Coupled;
  // (port type P, name, position in ports_) => a P owned by this model, placed in its inline
  // port store when it fits (a model's first ports take no heap block), else on the heap;
  // throws ModelError on a bad or duplicate name
  template <class P>
  P& addPort(std::string&& name, std::uint32_t at) {
    checkNewPort(name);
    ports_.reserve(ports_.size() + 1);
    const std::size_t from = (portStoreUsed_ + alignof(P) - 1) / alignof(P) * alignof(P);
    P* port;
    if (alignof(P) <= alignof(PortBase*) && from + sizeof(P) <= kPortStoreBytes) {
      port = ::new (static_cast<void*>(portStore_ + from)) P(*this, std::move(name));
      portStoreUsed_ = static_cast<std::uint16_t>(from + sizeof(P));
    } else {
      port = new P(*this, std::move(name));
    }
    ports_.insert(at, port);
    return *port;
  }
  // (name) => throws ModelError unless it is a valid, unused port name of this model
  void checkNewPort(std::string_view name) const;

  // () => every cached path is stale (a model was added somewhere, or a name hidden): paths are
  // recomputed when next asked for, so adding a subtree costs O(1), not a walk over it
  static void treeChanged() { treeGeneration_.fetch_add(1, std::memory_order_relaxed); }
  static std::atomic<std::uint64_t> treeGeneration_;

  struct PathCache {
    std::string path;
    std::uint64_t generation = 0;  // the tree generation path was computed in
  };

  std::string name_;
  mutable std::unique_ptr<PathCache> path_;  // made when a path is first asked for
  Coupled* parent_ = nullptr;
  bool hidden_ = false;
  std::uint16_t portStoreUsed_ = 0;  // bytes of portStore_ taken
  std::uint32_t nIn_ = 0;            // ports_[0, nIn_) are inputs, the rest outputs
  SmallVector<PortBase*, 2> ports_;
  // Room for two ports of small value types (an atomic's in and out) inside the model.
  static constexpr std::size_t kPortStoreBytes = 2 * sizeof(InPort<double>);
  alignas(PortBase*) std::byte portStore_[kPortStoreBytes];
};

// (name) => throws ModelError unless it is a valid model or port name (non-empty, no '.')
void checkName(std::string_view name, std::string_view what);

}  // namespace yardsim::devs
