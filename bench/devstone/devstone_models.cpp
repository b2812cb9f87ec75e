#include "devstone_models.hpp"

#include <charconv>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "devs/atomic.hpp"

namespace yardsim::bench::devstone {
namespace {

using devs::Time;

struct AtomicState {
  Time sigma = devs::kInfinity;
  std::uint64_t internal = 0;
  std::uint64_t external = 0;
};

class DevstoneAtomic final : public devs::Atomic<AtomicState> {
 public:
  explicit DevstoneAtomic(std::string name) : devs::Atomic<AtomicState>(std::move(name), {}) {}
  devs::InPort<int>& in = addInPort<int>("in");
  devs::OutPort<int>& out = addOutPort<int>("out");

 protected:
  Time timeAdvance(const AtomicState& s) const override { return s.sigma; }
  void output(const AtomicState& s) const override { out.add(static_cast<int>(s.external)); }
  void internalTransition(AtomicState& s) const override {
    ++s.internal;
    s.sigma = devs::kInfinity;
  }
  void externalTransition(AtomicState& s, Time) const override {
    ++s.external;
    s.sigma = 0.0;
  }
};

// One seed message at t = 0.
class Seeder final : public devs::Atomic<bool> {
 public:
  Seeder() : devs::Atomic<bool>("seeder", true) {}
  devs::OutPort<int>& out = addOutPort<int>("out");

 protected:
  Time timeAdvance(const bool& active) const override { return active ? 0.0 : devs::kInfinity; }
  void output(const bool&) const override { out.add(0); }
  void internalTransition(bool& active) const override { active = false; }
  void externalTransition(bool&, Time) const override {}
};

// (prefix, numbers) => "prefix1_2": built in place, one string (no to_string temporaries)
std::string numbered(std::string_view prefix, int a, int b = -1) {
  char buf[64];
  std::memcpy(buf, prefix.data(), prefix.size());
  char* end = std::to_chars(buf + prefix.size(), buf + sizeof buf, a).ptr;
  if (b >= 0) {
    *end++ = '_';
    end = std::to_chars(end, buf + sizeof buf, b).ptr;
  }
  return std::string(buf, end);
}

// (variant, depth, width) => one level of the DEVStone structure, recursively
std::unique_ptr<devs::Coupled> level(Variant v, int depth, int width) {
  auto c = std::make_unique<devs::Coupled>(numbered("coupled_", depth));
  const bool ho = v == Variant::HO || v == Variant::HOmod;
  auto& in = c->addInPort<int>("in");
  auto* in2 = ho ? &c->addInPort<int>("in2") : nullptr;
  auto& out = c->addOutPort<int>("out");
  auto* out2 = v == Variant::HO ? &c->addOutPort<int>("out2") : nullptr;
  if (depth == 1) {
    auto& a = c->add<DevstoneAtomic>("inner_atomic");
    c->couple(in, a.in);
    c->couple(a.out, out);
    return c;
  }
  auto& sub = static_cast<devs::Coupled&>(c->addComponent(level(v, depth - 1, width)));
  auto& subIn = *sub.findPort("in");
  c->couple(in, subIn);
  c->couple(*sub.findPort("out"), out);
  if (v == Variant::HO) c->couple(in, *sub.findPort("in2"));

  auto atomic = [&](std::string name) -> DevstoneAtomic& {
    return c->add<DevstoneAtomic>(std::move(name));
  };
  if (v != Variant::HOmod) {
    DevstoneAtomic* prev = nullptr;
    for (int i = 1; i < width; ++i) {
      auto& a = atomic(numbered("atomic_", i));
      c->couple(v == Variant::HO ? *in2 : in, a.in);
      if (v == Variant::HO) c->couple(a.out, *out2);
      if (prev && v != Variant::LI) c->couple(prev->out, a.in);
      prev = &a;
    }
    return c;
  }
  // HOmod: row 1 feeds the sub-model's in2; row 2 feeds all of row 1; row r >= 3 has one
  // atomic fewer than row r-1 and its i-th atomic feeds the (i+1)-th of row r-1; the first
  // atomic of every row and all of row 1 take in2.
  auto& subIn2 = *sub.findPort("in2");
  std::vector<DevstoneAtomic*> prev, cur;
  for (int i = 1; i < width; ++i) {
    auto& a = atomic(numbered("atomic_1_", i));
    c->couple(*in2, a.in);
    c->couple(a.out, subIn2);
    prev.push_back(&a);
  }
  for (int i = 1; i < width; ++i) {
    auto& a = atomic(numbered("atomic_2_", i));
    if (i == 1) c->couple(*in2, a.in);
    for (DevstoneAtomic* p : prev) c->couple(a.out, p->in);
    cur.push_back(&a);
  }
  for (int row = 3; row <= width; ++row) {
    prev.swap(cur);
    cur.clear();
    for (std::size_t i = 1; i < prev.size(); ++i) {
      auto& a = atomic(numbered("atomic_", row, static_cast<int>(i)));
      if (i == 1) c->couple(*in2, a.in);
      c->couple(a.out, prev[i]->in);
      cur.push_back(&a);
    }
  }
  return c;
}

void sum(const devs::Model& m, Counts& c) {
  if (auto* a = dynamic_cast<const DevstoneAtomic*>(&m)) {
    ++c.atomics;
    c.internal += a->state().internal;
    c.external += a->state().external;
  } else if (auto* k = dynamic_cast<const devs::Coupled*>(&m)) {
    for (const auto& child : k->components()) sum(*child, c);
  }
}

}  // namespace

std::unique_ptr<devs::Coupled> build(Variant v, int depth, int width) {
  if (depth < 1 || width < 1) throw std::invalid_argument("DEVStone depth and width must be >= 1");
  auto root = std::make_unique<devs::Coupled>("devstone");
  auto& seeder = root->add<Seeder>();
  auto& model = static_cast<devs::Coupled&>(root->addComponent(level(v, depth, width)));
  root->couple(seeder.out, *model.findPort("in"));
  if (v == Variant::HO || v == Variant::HOmod) root->couple(seeder.out, *model.findPort("in2"));
  return root;
}

Counts count(const devs::Coupled& root) {
  Counts c;
  sum(root, c);
  return c;
}

}  // namespace yardsim::bench::devstone
