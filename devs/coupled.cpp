#include "devs/coupled.hpp"

#include "devs/type_name.hpp"

namespace yardsim::devs {
namespace {

std::string describe(const PortBase& p) {
  return std::string(p.isInput() ? "input" : "output") + " port '" + p.name() + "' of model '" +
         p.owner().path() + "' (value type " + typeName(p.type()) + ")";
}

}  // namespace

Model& Coupled::addComponent(std::unique_ptr<Model> model) {
  if (!model) throw ModelError("coupled model '" + path() + "': null component");
  if (model->parent_)
    throw ModelError("model '" + model->path() + "' is already a component of another model");
  if (byName_.count(model->name()))
    throw ModelError("coupled model '" + path() + "' already has a component named '" +
                     model->name() + "'");
  model->parent_ = this;
  treeChanged();
  byName_.emplace(model->name(), model.get());
  components_.push_back(std::move(model));
  return *components_.back();
}

Model* Coupled::findComponent(std::string_view name) const {
  auto it = byName_.find(name);
  return it == byName_.end() ? nullptr : it->second;
}

void Coupled::coupleDirect(PortBase& from, PortBase& to) {
  auto below = [this](const Model& m) {
    for (const Model* p = m.parent(); p; p = p->parent())
      if (p == this) return true;
    return false;
  };
  if (!from.owner().isAtomic() || from.isInput() || !to.owner().isAtomic() || !to.isInput() ||
      !below(from.owner()) || !below(to.owner()))
    throw ModelError("in coupled model '" + path() + "': a direct coupling goes from an atomic's "
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
    throw ModelError("in coupled model '" + path() + "': cannot couple " + describe(from) +
                     " to " + describe(to) +
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
