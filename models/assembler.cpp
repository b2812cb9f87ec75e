#include "models/assembler.hpp"

#include <stdexcept>

#include "models/port_types.hpp"

namespace yardsim::models {
namespace {

// (instance, coupled model to fill) => its ports, components and couplings
void build(const Instance& inst, devs::Coupled& c) {
  for (const auto& p : inst.ports) {
    const PortType* type = findPortType(p.type);
    p.input ? type->addInput(c, p.name) : type->addOutput(c, p.name);
  }
  for (const auto& child : inst.children) {
    if (child->atomic()) {
      auto& m = c.addComponent(Registry::instance().create(*child->type, child->name, child->params));
      for (const auto& p : child->ports) {
        const devs::PortBase* made = m.findPort(p.name);
        if (!made || made->isInput() != p.input || portTypeName(made->type()) != p.type)
          throw std::logic_error("model type '" + child->type->name + "' declares " +
                                 (p.input ? "input" : "output") + " port '" + p.name + "' (" +
                                 p.type + ") but its model '" + m.path() + "' does not have it");
      }
    } else {
      auto sub = std::make_unique<devs::Coupled>(child->name);
      build(*child, *sub);
      c.addComponent(std::move(sub));
    }
  }
  auto port = [&](const std::string& model, const std::string& name) -> devs::PortBase& {
    devs::Model& owner = model.empty() ? static_cast<devs::Model&>(c) : *c.findComponent(model);
    return *owner.findPort(name);
  };
  for (const auto& k : inst.couplings) c.couple(port(k.fromModel, k.fromPort), port(k.toModel, k.toPort));
}

}  // namespace

std::unique_ptr<devs::Coupled> assemble(const Scene& scene) {
  auto root = std::make_unique<devs::Coupled>("scene");
  root->hideNameInPaths();
  build(scene.root, *root);
  return root;
}

}  // namespace yardsim::models
