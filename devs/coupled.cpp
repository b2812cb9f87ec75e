#include "devs/coupled.hpp"

#include <cstring>

#include "devs/type_name.hpp"

namespace yardsim::devs {
namespace {

std::string describe(const PortBase& p) {
  return std::string(p.isInput() ? "input" : "output") + " port '" + p.name() + "' of model '" +
         p.owner().path() + "' (value type " + typeName(p.type()) + ")";
}

}  // namespace

namespace {
// (name) => a 64-bit hash, eight bytes at a time (names are short: one or two words)
std::uint64_t nameHash(std::string_view name) {
  constexpr std::uint64_t k = 0x9e3779b97f4a7c15ull;
  std::uint64_t h = k ^ name.size();
  const char* p = name.data();
  std::size_t n = name.size();
  for (; n >= 8; n -= 8, p += 8) {
    std::uint64_t w;
    std::memcpy(&w, p, 8);
    h = (h ^ w) * k;
    h ^= h >> 32;
  }
  if (n > 0) {
    std::uint64_t w = 0;
    std::memcpy(&w, p, n);
    h = (h ^ w) * k;
  }
  h ^= h >> 29;
  h *= 0xbf58476d1ce4e5b9ull;
  return h ^ (h >> 32);
}

// (name index, position i, its name's hash) => i in the first free slot from the hash on
void place(ListVector<std::uint32_t>& index, std::uint32_t i, std::uint64_t hash) {
  const std::size_t mask = index.size() / 2 - 1;
  std::size_t s = hash & mask;
  while (index[2 * s] != 0) s = (s + 1) & mask;
  index[2 * s] = i + 1;
  index[2 * s + 1] = static_cast<std::uint32_t>(hash);
}
}  // namespace

Model& Coupled::addComponent(std::unique_ptr<Model> model) {
  if (!model) throw ModelError("coupled model '" + path() + "': null component");
  if (model->parent_)
    throw ModelError("model '" + model->path() + "' is already a component of another model");
  const std::uint64_t hash = nameHash(model->name());
  if (find(model->name(), hash))
    throw ModelError("coupled model '" + path() + "' already has a component named '" +
                     model->name() + "'");
  model->parent_ = this;
  treeChanged();
  components_.push_back(std::move(model));
  if (components_.size() > kLinearNames)
    index(static_cast<std::uint32_t>(components_.size() - 1), hash);
  return *components_.back();
}

// index_ holds slots of two entries: the component's position + 1 (0: an empty slot) and the low
// 32 bits of its name's hash, so a probe compares names only when the hashes agree and a
// rebuilt table re-inserts without hashing the names again.
Model* Coupled::find(std::string_view name, std::uint64_t hash) const {
  if (index_.empty()) {
    for (const auto& c : components_)
      if (c->name() == name) return c.get();
    return nullptr;
  }
  const std::size_t mask = index_.size() / 2 - 1;
  const auto low = static_cast<std::uint32_t>(hash);
  for (std::size_t s = hash & mask;; s = (s + 1) & mask) {
    const std::uint32_t k = index_[2 * s];
    if (k == 0) return nullptr;
    if (index_[2 * s + 1] != low) continue;
    Model* m = components_[k - 1].get();
    if (m->name() == name) return m;
  }
}

void Coupled::index(std::uint32_t i, std::uint64_t hash) {
  // (components) => a table at most half full, at least a quarter; rebuilt when it grows
  if (2 * components_.size() > index_.size() / 2) {
    std::size_t slots = 4 * kLinearNames;
    while (slots < 2 * components_.size()) slots *= 2;
    ListVector<std::uint32_t> old(std::move(index_));
    index_.assign(2 * slots, 0);
    if (old.empty()) {
      for (std::uint32_t j = 0; j < i; ++j) place(index_, j, nameHash(components_[j]->name()));
    } else {
      for (std::size_t s = 0; s < old.size(); s += 2)
        if (old[s] != 0) place(index_, old[s] - 1, old[s + 1]);
    }
  }
  place(index_, i, hash);
}

Model* Coupled::findComponent(std::string_view name) const {
  return find(name, nameHash(name));
}

void Coupled::coupleDirect(PortBase& from, PortBase& to) {
  auto below = [this](const Model& m) {
    for (const Model* p = m.parent(); p; p = p->parent())
      if (p == this) return true;
    return false;
  };
  if (!from.owner().isAtomic() || from.isInput() || !to.owner().isAtomic() || !to.isInput() ||
      !below(from.owner()) || !below(to.owner()))
    throw ModelError("in coupled model '" + path() +
                     "': a direct coupling goes from an atomic's "
                     "output to an atomic's input, both below this model; cannot couple " +
                     describe(from) + " to " + describe(to));
  if (from.type() != to.type())
    throw ModelError("in coupled model '" + path() + "': value types differ: " + describe(from) +
                     " cannot feed " + describe(to));
  from.links_.push_back(&to);
  ++couplings_;
}

void Coupled::couple(PortBase& from, PortBase& to) {
  const Model& src = from.owner();
  const Model& dst = to.owner();
  const bool eic = &src == this && from.isInput() && dst.parent() == this && to.isInput();
  const bool ic = src.parent() == this && !from.isInput() && dst.parent() == this && to.isInput();
  const bool eoc = src.parent() == this && !from.isInput() && &dst == this && !to.isInput();
  if (!eic && !ic && !eoc) {
    throw ModelError("in coupled model '" + path() + "': cannot couple " + describe(from) + " to " +
                     describe(to) +
                     "; a coupling goes from this model's input to a component's input, from a "
                     "component's output to a component's input, or from a component's output "
                     "to this model's output");
  }
  if (from.type() != to.type()) {
    throw ModelError("in coupled model '" + path() + "': value types differ: " + describe(from) +
                     " cannot feed " + describe(to));
  }
  from.links_.push_back(&to);
  ++couplings_;
}

}  // namespace yardsim::devs
