#include "scene/assembler.hpp"

#include <stdexcept>

#include "mechanics/build.hpp"
#include "scene/mechanical_systems.hpp"
#include "models/multibody/multibody_model.hpp"
#include "models/port_types.hpp"

namespace yardsim::scene {

using mechanics::buildMechanics;
using models::MultibodyModel;
using models::MultibodyOptions;
using models::PortType;
using models::Registry;
using models::findPortType;
using models::portTypeName;
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


// (instance path) => the DEVS model at that path below root
devs::Model& modelAt(devs::Coupled& root, const std::string& path) {
  devs::Model* m = &root;
  std::size_t start = 0;
  while (start <= path.size()) {
    const auto dot = path.find('.', start);
    const std::string name = path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    m = static_cast<devs::Coupled*>(m)->findComponent(name);
    if (!m) throw std::logic_error("assembler: no model at '" + path + "'");
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return *m;
}

// (instance tree) => actors bound to a scene mechanical system, coupled to it directly, and
// actors listening to the actors their start rules name
void bindActors(const Instance& inst, devs::Coupled& root) {
  for (const auto& child : inst.children) {
    if (!child->atomic()) {
      bindActors(*child, root);
      continue;
    }
    devs::Model& actor = modelAt(root, child->path);
    // (start rule resolved by bindStartRules) => the named actors' `finished` into `trigger`
    for (const auto& from : child->listensTo)
      root.coupleDirect(*modelAt(root, from).findPort("finished"), *actor.findPort("trigger"));
    if (child->boundSystem.empty()) continue;
    devs::Model& mb = *root.findComponent(child->boundSystem);
    root.coupleDirect(*actor.findPort("setpoint"), *mb.findPort("setpoint"));
    root.coupleDirect(*mb.findPort("event"), *actor.findPort("event"));
  }
}

}  // namespace

std::unique_ptr<devs::Coupled> assemble(const Scene& scene) {
  auto root = std::make_unique<devs::Coupled>("scene");
  root->hideNameInPaths();
  build(scene.root, *root);
  // (mechanical systems) => one multibody model each, at the scene root
  for (const auto& system : scene.systems) {
    MultibodyOptions opt;
    opt.dt = scene.dt;
    opt.integrator = scene.integratorSpec;
    opt.elementPaths = true;
    const auto& set = system->spec.settings;
    opt.driveBandwidth = set.driveBandwidth;
    opt.driveMaxEffort = set.driveMaxEffort;
    opt.driveTolerance = set.driveTolerance;
    opt.equilibrium = set.equilibrium;
    root->addComponent(std::make_unique<MultibodyModel>(
        system->name, system->built ? *system->built : buildMechanics(system->spec), opt));
  }
  bindActors(scene.root, *root);
  return root;
}

}  // namespace yardsim::scene
