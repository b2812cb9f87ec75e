#pragma once
// Coupled models: components (atomic or coupled, any depth) and couplings between their
// ports. External input couplings (this.in -> child.in), internal couplings
// (child.out -> child.in) and external output couplings (child.out -> this.out) are checked
// when they are added: direction, ownership and value type.
#include <cstdint>
#include <memory>
#include <string_view>
#include <utility>
#include <vector>

#include "devs/model.hpp"
#include "devs/model_arena.hpp"

namespace yardsim::devs {

class Coupled : public Model {
 public:
  explicit Coupled(std::string name) : Model(std::move(name)) {}
  bool isAtomic() const final { return false; }

  // (model) => owned child; throws ModelError on a duplicate name or a model already placed
  Model& addComponent(std::unique_ptr<Model> model);
  template <class M, class... Args>
  M& add(Args&&... args) {
    return static_cast<M&>(addComponent(std::make_unique<M>(std::forward<Args>(args)...)));
  }

  // (from port, to port) => coupling; throws ModelError naming both ports, their value types
  // and their models' paths when the types differ or the direction is not EIC, IC or EOC
  void couple(PortBase& from, PortBase& to);

  // (atomic output port, atomic input port, both anywhere below this model) => a direct
  // coupling across the hierarchy. For what follows paths rather than the DEVS hierarchy: an
  // actor's set-points reach the multibody model that owns the element it names. Throws
  // ModelError like couple().
  void coupleDirect(PortBase& from, PortBase& to);

  // Components in the order they were added (a list in the model arena, devs/model_arena.hpp).
  using Components = ListVector<std::unique_ptr<Model>>;
  const Components& components() const { return components_; }
  Model* findComponent(std::string_view name) const;
  std::size_t couplingCount() const { return couplings_; }

 private:
  // (name, its hash) => the component of that name, or nullptr
  Model* find(std::string_view name, std::uint64_t hash) const;
  // (component at position i, its name's hash) => in the name index (rebuilt when half full)
  void index(std::uint32_t i, std::uint64_t hash);

  Components components_;
  // Name index over components_, built once there are more than kLinearNames of them: open
  // addressing, a power-of-two number of slots of two entries: (position + 1, 0 for an empty
  // slot) and the low 32 bits of the name's hash. One array, so adding a component takes no heap
  // block of its own; in the model arena, as components_.
  static constexpr std::size_t kLinearNames = 8;
  ListVector<std::uint32_t> index_;
  std::size_t couplings_ = 0;
};

}  // namespace yardsim::devs
