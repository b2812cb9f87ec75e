#pragma once
// Typed ports. A port holds the bag of messages of the current event time; the Simulator
// copies bags along the flattened couplings and clears them after the transitions, so in the
// steady state a message costs a copy and no heap allocation (bags keep their capacity).
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <typeinfo>
#include <utility>
#include <vector>

#include "devs/small_vector.hpp"
#include "devs/trace_format.hpp"

namespace yardsim::devs {

class Model;
class Coupled;

class PortBase {
 public:
  PortBase(Model& owner, std::string&& name, bool isInput, const std::type_info& type)
      : isInput_(isInput), owner_(&owner), name_(std::move(name)), type_(&type) {}
  virtual ~PortBase() = default;
  PortBase(const PortBase&) = delete;
  PortBase& operator=(const PortBase&) = delete;

  const std::string& name() const { return name_; }
  Model& owner() const { return *owner_; }
  bool isInput() const { return isInput_; }
  const std::type_info& type() const { return *type_; }
  // () => "<owner path>.<port name>"
  std::string path() const;

  std::size_t size() const { return count_; }
  bool empty() const { return count_ == 0; }
  // (bag) => empty bag, capacity kept
  virtual void clear() = 0;
  // (this bag, dst of the same value type) => dst bag += this bag
  virtual void appendTo(PortBase& dst) const = 0;
  // (message i) => its JSON form appended to out
  virtual void writeValue(std::string& out, std::size_t i) const = 0;

  // Couplings leaving this port, in the coupled model that declared them (read by flatten).
  std::span<PortBase* const> links() const { return links_.span(); }

 protected:
  std::uint32_t count_ = 0;  // messages in the bag

 private:
  friend class Coupled;
  bool isInput_;  // packed with count_
  Model* owner_;
  std::string name_;
  const std::type_info* type_;
  SmallVector<PortBase*, 1> links_;  // most atomic ports have at most one coupling
};

template <class T>
class Port : public PortBase {
 public:
  using value_type = T;
  Port(Model& owner, std::string&& name, bool isInput)
      : PortBase(owner, std::move(name), isInput, typeid(T)) {}

  const std::vector<T>& values() const { return bag_; }

  void clear() final {
    bag_.clear();
    count_ = 0;
  }
  void appendTo(PortBase& dst) const final {
    auto& to = static_cast<Port<T>&>(dst);  // flatten checked the types
    if (bag_.size() == 1)
      to.bag_.push_back(bag_.front());  // the common case, without a range insert's memmove
    else
      to.bag_.insert(to.bag_.end(), bag_.begin(), bag_.end());
    to.count_ = static_cast<std::uint32_t>(to.bag_.size());
  }
  void writeValue(std::string& out, std::size_t i) const final {
    TraceFormat<T>::write(out, bag_[i]);
  }

 protected:
  std::vector<T> bag_;
};

template <class T>
class InPort final : public Port<T> {
 public:
  InPort(Model& owner, std::string&& name) : Port<T>(owner, std::move(name), true) {}
};

template <class T>
class OutPort final : public Port<T> {
 public:
  OutPort(Model& owner, std::string&& name) : Port<T>(owner, std::move(name), false) {}
  // (value) => appended to this event time's output bag; call only from an output function
  void add(const T& value) {
    this->bag_.push_back(value);
    ++this->count_;
  }
  void add(T&& value) {
    this->bag_.push_back(std::move(value));
    ++this->count_;
  }
};

}  // namespace yardsim::devs
