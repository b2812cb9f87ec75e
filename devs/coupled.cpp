#include "devs/coupled.hpp"

#include "devs/type_name.hpp"

namespace yardsim::devs {
namespace {

std::string describe(const PortBase& p) {
  return std::string(p.isInput() ? "input" : "output") + " port '" + p.name() + "' of model '" +
         p.owner().path() + "' (value type " + typeName(p.type()) + ")";
}

}  // namespace

namespace {
// (name) => its 64-bit FNV-1a hash
std::uint64_t nameHash(std::string_view name) {
  std::uint64_t h = 14695981039346656037ull;
  for (const char c : name) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
  return h;
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

Model* Coupled::find(std::string_view name, std::uint64_t hash) const {
  if (index_.empty()) {
    for (const auto& c : components_)
      if (c->name() == name) return c.get();
    return nullptr;
  }
  const std::size_t mask = index_.size() - 1;
  for (std::size_t s = hash & mask;; s = (s + 1) & mask) {
    const std::uint32_t k = index_[s];
    if (k == 0) return nullptr;
    Model* m = components_[k - 1].get();
    if (m->name() == name) return m;
  }
}

void Coupled::index(std::uint32_t i, std::uint64_t hash) {
  // (components) => a table at most half full; all of them re-inserted when it grows
  if (2 * components_.size() > index_.size()) {
    std::size_t size = 4 * kLinearNames;
    while (size < 4 * components_.size()) size *= 2;
    index_.assign(size, 0);
    for (std::uint32_t j = 0; j < i; ++j) index(j, nameHash(components_[j]->name()));
  }
  const std::size_t mask = index_.size() - 1;
  std::size_t s = hash & mask;
  while (index_[s] != 0) s = (s + 1) & mask;
  index_[s] = i + 1;
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
