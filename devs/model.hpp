#pragma once
// Common base of atomic and coupled models: a name, a parent, typed input and output ports.
#include <atomic>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "devs/port.hpp"

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

  const std::vector<std::unique_ptr<PortBase>>& inPorts() const { return in_; }
  const std::vector<std::unique_ptr<PortBase>>& outPorts() const { return out_; }
  // (name) => input or output port of that name, or nullptr
  PortBase* findPort(std::string_view name) const;

  template <class T>
  InPort<T>& addInPort(std::string name) {
    return static_cast<InPort<T>&>(
        registerPort(std::make_unique<InPort<T>>(*this, std::move(name)), in_));
  }
  template <class T>
  OutPort<T>& addOutPort(std::string name) {
    return static_cast<OutPort<T>&>(
        registerPort(std::make_unique<OutPort<T>>(*this, std::move(name)), out_));
  }

 private:
  friend class Coupled;
  PortBase& registerPort(std::unique_ptr<PortBase> port,
                         std::vector<std::unique_ptr<PortBase>>& list);

  // () => every cached path is stale (a model was added somewhere, or a name hidden): paths are
  // recomputed when next asked for, so adding a subtree costs O(1), not a walk over it
  static void treeChanged() { treeGeneration_.fetch_add(1, std::memory_order_relaxed); }
  static std::atomic<std::uint64_t> treeGeneration_;

  std::string name_;
  mutable std::string path_;
  mutable std::uint64_t pathGeneration_ = 0;  // the tree generation path_ was computed in
  Coupled* parent_ = nullptr;
  bool hidden_ = false;
  std::vector<std::unique_ptr<PortBase>> in_;
  std::vector<std::unique_ptr<PortBase>> out_;
};

// (name) => throws ModelError unless it is a valid model or port name (non-empty, no '.')
void checkName(std::string_view name, std::string_view what);

}  // namespace yardsim::devs
