#include "scene/resolved_listing.hpp"

#include "scene/mechanical_systems.hpp"

#include <cmath>
#include <sstream>

namespace yardsim::scene {
namespace {

std::string flow(const YAML::Node& n) {
  YAML::Emitter e;
  e.SetMapFormat(YAML::Flow);
  e.SetSeqFormat(YAML::Flow);
  e << n;
  return e.c_str();
}

void instances(const Instance& inst, std::ostringstream& os, int& atomics, int& coupled) {
  for (const auto& c : inst.children) {
    if (c->atomic()) {
      ++atomics;
      os << "  atomic  " << c->path << "  type=" << c->type->name;
      for (const auto& [k, v] : c->params.values()) os << "  " << k << "=" << flow(v);
      os << "\n";
    } else {
      ++coupled;
      os << "  coupled " << c->path;
      if (!c->source.empty()) os << "  from=" << c->source;
      os << "\n";
      instances(*c, os, atomics, coupled);
    }
  }
}

void couplings(const Instance& inst, std::ostringstream& os) {
  auto full = [&](const std::string& model, const std::string& port) {
    std::string p = inst.path;
    if (!model.empty()) p += (p.empty() ? "" : ".") + model;
    return (p.empty() ? std::string("<scene>") : p) + "." + port;
  };
  for (const auto& k : inst.couplings)
    os << "  " << full(k.fromModel, k.fromPort) << " -> " << full(k.toModel, k.toPort) << "\n";
  for (const auto& c : inst.children) couplings(*c, os);
}

}  // namespace

std::string resolvedListing(const Scene& s) {
  std::ostringstream body, os;
  int atomics = 0, coupled = 0;
  instances(s.root, body, atomics, coupled);
  os << "scene " << s.name << " (" << s.file.string() << ", sha256 " << s.sha256 << ")\n"
     << "run: until=" << (std::isinf(s.until) ? std::string("no event left") : std::to_string(s.until))
     << " seed=" << s.seed << " integrator=" << s.integrator << " dt=" << s.dt << "\n"
     << "models: " << atomics << " atomic, " << coupled << " coupled\n"
     << body.str() << "couplings:\n";
  couplings(s.root, os);
  for (const auto& sys : s.systems) {
    os << "mechanical system " << sys->name << " (multibody at the scene root):";
    for (const auto& b : sys->spec.bodies) os << " " << b.name;
    for (const auto& r : sys->spec.ropes) os << " rope:" << r.name;
    for (const auto& e : sys->spec.equalizers) os << " equalizer:" << e.name;
    for (const auto& l : sys->spec.loops) os << " loop:" << l.name;
    for (const auto& h : sys->spec.hulls) os << " hydrostatics:" << h.name;
    for (const auto& w : sys->spec.windLoads) os << " wind_load:" << w.name;
    for (const auto& c : sys->spec.currentLoads) os << " current_load:" << c.name;
    for (const auto& d : sys->spec.dampers) os << " damping:" << d.name;
    os << "\n";
  }
  if (!s.database.empty()) {  // where each value from the yard database came from
    os << "database " << s.database << "\n";
    for (const auto& pv : s.provenance)
      os << "  " << pv.key << " = " << pv.value << "  <- " << pv.source << "\n";
  }
  for (const auto& h : s.hookLoads) {  // cranes whose hook-load curve the run checks
    os << "hook-load check " << h.crane << " (facility " << h.facility << ", from " << h.root
       << "):";
    for (const auto& [rope, parts] : h.ropes) os << " " << rope << " x" << parts;
    os << "; curve";
    for (const auto& [r, c] : h.curve) os << " " << r << " m: " << c << " N";
    os << "\n";
  }
  os << "recorder: ";
  if (s.record.interval > 0) {
    os << "every " << s.record.interval << " s, channels";
    for (const auto& g : s.record.channels) os << " " << g;
    os << "\n";
  } else {
    os << "none\n";
  }
  os << "trace sinks:";
  for (const auto& t : s.trace) os << " " << t;
  os << (s.trace.empty() ? " none\n" : "\n");
  return os.str();
}

}  // namespace yardsim::scene
