#include "devs/flatten.hpp"

#include <catch2/catch.hpp>
#include <memory>
#include <string>
#include <vector>

#include "devs/coupled.hpp"
#include "support/gpt_builders.hpp"
#include "support/test_models.hpp"

using namespace yardsim;

TEST_CASE("flattening reaches atomic inputs through every level") {
  auto gpt = testing::makeGpt(testing::GptParameters{});
  const auto flat = devs::flatten(*gpt);
  REQUIRE(flat.atomics.size() == 3);
  CHECK(flat.atomics[0]->path() == "gpt.ef.genr");
  CHECK(flat.atomics[1]->path() == "gpt.ef.transd");
  CHECK(flat.atomics[2]->path() == "gpt.proc");
  for (std::uint32_t i = 0; i < 3; ++i) CHECK(flat.atomics[i]->simIndex() == i);
  // genr.out reaches transd.arrived (IC) and proc.in (EOC then IC at the top)
  const std::uint32_t genrOut = flat.outBegin[0];
  std::vector<std::string> reached;
  for (auto k = flat.outs[genrOut].destFirst; k < flat.outs[genrOut].destLast; ++k)
    reached.push_back(flat.destPorts[k]->path());
  std::sort(reached.begin(), reached.end());
  CHECK(reached == std::vector<std::string>{"gpt.ef.transd.arrived", "gpt.proc.in"});
  // proc.out reaches transd.solved (IC at the top, then EIC into ef)
  const std::uint32_t procOut = flat.outBegin[2];
  REQUIRE(flat.outs[procOut].destLast - flat.outs[procOut].destFirst == 1);
  CHECK(flat.outs[procOut].port->path() == "gpt.proc.out");
  CHECK(flat.destPorts[flat.outs[procOut].destFirst]->path() == "gpt.ef.transd.solved");
  CHECK(flat.destAtomics[flat.outs[procOut].destFirst] == 1);
}

TEST_CASE(
    "flattening a deep hierarchy: depth-first order, routes in stack order, lists sized once") {
  // root: emitter e, then c<D>; c<k>: collector a<k>, c<k-1>, collector b<k>; c<k>.in feeds
  // a<k>.in and c<k-1>.in, so e.out reaches every a<k> through up to D levels
  constexpr int depth = 1500;
  auto root = std::make_unique<devs::Coupled>("root");
  auto& e = root->add<testing::Emitter>("e", std::vector<devs::Time>{1.0});
  std::unique_ptr<devs::Coupled> below;
  for (int k = 1; k <= depth; ++k) {
    auto c = std::make_unique<devs::Coupled>("c" + std::to_string(k));
    auto& in = c->addInPort<int>("in");
    auto& a = c->add<testing::Collector>("a" + std::to_string(k));
    c->couple(in, a.in);
    if (below) {
      auto& sub = static_cast<devs::Coupled&>(c->addComponent(std::move(below)));
      c->couple(in, *sub.findPort("in"));
    }
    c->add<testing::Collector>("b" + std::to_string(k));
    below = std::move(c);
  }
  auto& top = static_cast<devs::Coupled&>(root->addComponent(std::move(below)));
  root->couple(e.out, *top.findPort("in"));

  const auto flat = devs::flatten(*root);
  REQUIRE(flat.atomics.size() == 1 + 2 * depth);
  // (hierarchy) => e, a<D> .. a<1>, b<1> .. b<D>
  CHECK(flat.atomics[0]->name() == "e");
  bool ordered = true;
  for (int k = 1; k <= depth; ++k) {
    ordered = ordered && flat.atomics[1 + depth - k]->name() == "a" + std::to_string(k) &&
              flat.atomics[depth + k]->name() == "b" + std::to_string(k);
  }
  CHECK(ordered);
  for (std::uint32_t i = 0; i < flat.atomics.size(); ++i) CHECK(flat.atomics[i]->simIndex() == i);

  // (e.out) => a<1> .. a<D>: the deepest first, as a stack seeded with the links delivers them
  const std::uint32_t eOut = flat.outBegin[0];
  REQUIRE(flat.outs[eOut].destLast - flat.outs[eOut].destFirst == depth);
  bool routed = true;
  for (int k = 1; k <= depth; ++k) {
    const std::uint32_t d = flat.outs[eOut].destFirst + static_cast<std::uint32_t>(k - 1);
    routed = routed && flat.destPorts[d]->owner().name() == "a" + std::to_string(k) &&
             flat.destAtomics[d] == static_cast<std::uint32_t>(1 + depth - k);
  }
  CHECK(routed);
  // every output port listed (e.out, then each collector's tick), no tick routed anywhere
  CHECK(flat.outBegin.back() == 1 + 2 * depth);
  CHECK(flat.outs.size() == 1 + 2 * depth);
  CHECK(flat.outs.back().destLast == depth);
  // (counted first) => each list one block of its final size
  CHECK(flat.atomics.capacity() == flat.atomics.size());
  CHECK(flat.outBegin.capacity() == flat.outBegin.size());
  CHECK(flat.outs.capacity() == flat.outs.size());
  CHECK(flat.destPorts.capacity() == flat.destPorts.size());
  CHECK(flat.destAtomics.capacity() == flat.destAtomics.size());
}
