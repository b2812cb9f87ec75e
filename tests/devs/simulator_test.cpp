#include "devs/simulator.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <tuple>

#include "devs/coupled.hpp"
#include "support/gpt_builders.hpp"
#include "support/record_collector.hpp"
#include "models/library/delay.hpp"
#include "support/test_models.hpp"

using namespace yardsim;
using namespace yardsim::testing;
using devs::Coupled;
using devs::Simulator;

namespace {

// (records) => (t, leaf model name, kind, port, value) sorted within each event time, so a
// hierarchy and its flat form can be compared whatever their paths and routing order.
std::vector<std::tuple<double, std::string, std::string, std::string, std::string>> normalised(
    const std::vector<Record>& records) {
  std::vector<std::tuple<double, std::string, std::string, std::string, std::string>> out;
  for (const auto& r : records)
    out.emplace_back(r.t, r.model.substr(r.model.rfind('.') + 1), r.kind, r.port, r.value);
  std::stable_sort(out.begin(), out.end());
  return out;
}

std::vector<Record> traceOf(devs::Model& root, devs::Time until = devs::kInfinity) {
  Simulator sim(root);
  RecordCollector rec;
  sim.addListener(rec);
  sim.runUntil(until);
  return rec.records;
}

}  // namespace

TEST_CASE("a three-level hierarchy gives the same trace as its flattened form") {
  testing::GptParameters p{1.0, 1.5, 20.0};
  auto hier = testing::makeGpt(p);
  auto flat = testing::makeFlatGpt(p);
  const auto a = traceOf(*hier);
  const auto b = traceOf(*flat);
  REQUIRE(a.size() > 50);
  CHECK(normalised(a) == normalised(b));
  // the paths in the hierarchical trace name every level
  CHECK(std::any_of(a.begin(), a.end(), [](const Record& r) { return r.model == "gpt.ef.genr"; }));
}

TEST_CASE("a processor nested four levels deep behaves as when it sits at the top") {
  auto deep = std::make_unique<Coupled>("root");
  auto& gen = deep->add<Emitter>("gen", std::vector<devs::Time>{0.5, 1.0, 4.0}, 2);
  auto& l1 = deep->add<Coupled>("l1");
  auto& l1in = l1.addInPort<int>("in");
  auto& l1out = l1.addOutPort<int>("out");
  auto& l2 = l1.add<Coupled>("l2");
  auto& l2in = l2.addInPort<int>("in");
  auto& l2out = l2.addOutPort<int>("out");
  auto& relay = l2.add<models::library::Delay>("relay", 0.25);
  auto& sink = deep->add<Collector>("sink");
  deep->couple(gen.out, l1in);
  l1.couple(l1in, l2in);
  l2.couple(l2in, relay.in);
  l2.couple(relay.out, l2out);
  l1.couple(l2out, l1out);
  deep->couple(l1out, sink.in);

  auto flat = std::make_unique<Coupled>("root");
  auto& gen2 = flat->add<Emitter>("gen", std::vector<devs::Time>{0.5, 1.0, 4.0}, 2);
  auto& relay2 = flat->add<models::library::Delay>("relay", 0.25);
  auto& sink2 = flat->add<Collector>("sink");
  flat->couple(gen2.out, relay2.in);
  flat->couple(relay2.out, sink2.in);

  CHECK(normalised(traceOf(*deep)) == normalised(traceOf(*flat)));
  REQUIRE(sink.state().bags.size() == 3);
  CHECK(sink.state().bags[0].first == Approx(0.75));
  CHECK(sink.state().bags[2].first == Approx(4.25));
  CHECK(sink.state().bags[1].second == std::vector<int>{100, 101});
}

TEST_CASE("internal and external events at the same time make a confluent transition") {
  Coupled root("root");
  auto& gen = root.add<Emitter>("gen", std::vector<devs::Time>{1.0, 2.5});
  auto& col = root.add<Collector>("col", 1.0);  // fires at 1, 2, 3, ...
  root.couple(gen.out, col.in);
  Simulator sim(root);
  sim.runUntil(3.0);
  const auto& s = col.state();
  CHECK(s.confluent == 1);          // t = 1: own event and the emitter's message together
  CHECK(s.lastConfluentE == 1.0);   // elapsed time since the last transition (t = 0)
  CHECK(s.external == 1);           // t = 2.5
  CHECK(s.internal == 2);           // t = 2 and t = 3
  CHECK(sim.stats().confluent == 1);
  REQUIRE(s.bags.size() == 2);
  CHECK(s.bags[0].first == 1.0);
  CHECK(s.bags[1].first == 2.5);
}

namespace {
// One hook a listener received: which listener, 'S'tart, 'O'utput, 'I'nput, 'T'ransition, state
// 'X' or 'E'nd, and the model of a transition or state.
struct Hook {
  int listener;
  char kind;
  const devs::AtomicBase* model;
};
// Logs each hook it receives into a log shared with other listeners.
struct HookLog : devs::Listener {
  HookLog(int i, std::vector<Hook>& l) : id(i), log(l) {}
  int id;
  std::vector<Hook>& log;
  void onStart(devs::Time, std::span<devs::AtomicBase* const>) override {
    log.push_back({id, 'S', nullptr});
  }
  void onOutput(devs::Time, const devs::AtomicBase&, const devs::PortBase&) override {
    log.push_back({id, 'O', nullptr});
  }
  void onInput(devs::Time, const devs::AtomicBase&, const devs::PortBase&) override {
    log.push_back({id, 'I', nullptr});
  }
  void onTransition(devs::Time, const devs::AtomicBase& m, devs::Transition, devs::Time) override {
    log.push_back({id, 'T', &m});
  }
  void onState(devs::Time, const devs::AtomicBase& m) override { log.push_back({id, 'X', &m}); }
  void onEnd(devs::Time) override { log.push_back({id, 'E', nullptr}); }
};
}  // namespace

TEST_CASE("a listener hears a transition's state right after the transition, nothing between") {
  // (internal, external and confluent transitions, two listeners) => every 'T' is followed at once
  // by the 'X' of the same listener and model, no other listener's hook between them
  // (run/profile.hpp times the two hooks as one)
  Coupled root("root");
  auto& gen = root.add<Emitter>("gen", std::vector<devs::Time>{1.0, 2.5}, 2);
  auto& col = root.add<Collector>("col", 1.0);
  root.couple(gen.out, col.in);
  Simulator sim(root);
  std::vector<Hook> log;
  HookLog first(1, log), second(2, log);
  sim.addListener(first);
  sim.addListener(second);
  sim.runUntil(4.0);
  CHECK(col.state().confluent == 1);
  CHECK(col.state().external == 1);
  int transitions = 0;
  for (std::size_t i = 0; i < log.size(); ++i) {
    if (log[i].kind != 'T') continue;
    ++transitions;
    REQUIRE(i + 1 < log.size());
    CHECK(log[i + 1].kind == 'X');
    CHECK(log[i + 1].listener == log[i].listener);
    CHECK(log[i + 1].model == log[i].model);
  }
  CHECK(transitions >= 2 * 7);  // gen at 1 and 2.5, col at 1 (conf), 2, 2.5 (ext), 3 and 4
}

TEST_CASE("several messages on one port arrive in one bag") {
  Coupled root("root");
  auto& a = root.add<Emitter>("a", std::vector<devs::Time>{2.0}, 3);
  auto& b = root.add<Emitter>("b", std::vector<devs::Time>{2.0}, 1);
  auto& col = root.add<Collector>("col");
  root.couple(a.out, col.in);
  root.couple(b.out, col.in);
  Simulator sim(root);
  sim.run();
  REQUIRE(col.state().external == 1);
  auto bag = col.state().bags.at(0).second;
  std::sort(bag.begin(), bag.end());
  CHECK(bag == std::vector<int>{0, 0, 1, 2});
  CHECK(sim.stats().messages == 4);
}

TEST_CASE("a message reaching a port along two coupling paths is delivered twice") {
  Coupled root("root");
  auto& gen = root.add<Emitter>("gen", std::vector<devs::Time>{1.0});
  auto& box = root.add<Coupled>("box");
  auto& boxIn = box.addInPort<int>("in");
  auto& boxOut = box.addOutPort<int>("out");
  auto& relay = box.add<models::library::Delay>("relay", 0.0);
  box.couple(boxIn, relay.in);
  box.couple(relay.out, boxOut);
  auto& col = root.add<Collector>("col");
  root.couple(gen.out, boxIn);
  root.couple(gen.out, boxIn);  // a second coupling between the same ports
  root.couple(boxOut, col.in);
  Simulator sim(root);
  sim.run();
  REQUIRE(col.state().bags.size() == 1);
  CHECK(col.state().bags[0].second.size() == 2);
}

TEST_CASE("zero-delay chains run as successive steps at the same time") {
  Coupled root("root");
  auto& gen = root.add<Emitter>("gen", std::vector<devs::Time>{1.0});
  auto& r1 = root.add<models::library::Delay>("r1", 0.0);
  auto& r2 = root.add<models::library::Delay>("r2", 0.0);
  auto& col = root.add<Collector>("col");
  root.couple(gen.out, r1.in);
  root.couple(r1.out, r2.in);
  root.couple(r2.out, col.in);
  Simulator sim(root);
  int steps = 0;
  while (sim.step()) {
    ++steps;
    CHECK(sim.time() == 1.0);
  }
  CHECK(steps == 3);
  REQUIRE(col.state().bags.size() == 1);
  CHECK(col.state().bags[0].first == 1.0);
}

TEST_CASE("run until a time, until no event is left, or one event time per call") {
  Coupled root("root");
  auto& gen = root.add<Emitter>("gen", std::vector<devs::Time>{1.0, 2.0, 5.0});
  auto& col = root.add<Collector>("col");
  root.couple(gen.out, col.in);
  Simulator sim(root);
  CHECK(sim.nextEventTime() == 1.0);
  REQUIRE(sim.step());
  CHECK(sim.time() == 1.0);
  CHECK(col.state().bags.size() == 1);
  sim.runUntil(3.0);
  CHECK(sim.time() == 3.0);
  CHECK(col.state().bags.size() == 2);
  CHECK(sim.nextEventTime() == 5.0);
  sim.run();
  CHECK(col.state().bags.size() == 3);
  CHECK(sim.nextEventTime() == devs::kInfinity);
  CHECK_FALSE(sim.step());
}

namespace {
struct Broken final : devs::Atomic<int> {
  Broken() : devs::Atomic<int>("broken", 0) {}
  devs::Time timeAdvance(const int& s) const override { return s == 0 ? 1.0 : -1.0; }
  void output(const int&) const override {}
  void internalTransition(int& s) const override { s = 1; }
  void externalTransition(int&, devs::Time) const override {}
};
}  // namespace

TEST_CASE("a negative time advance stops the run naming the model") {
  Coupled root("top");
  root.add<Broken>();
  Simulator sim(root);
  REQUIRE_THROWS_WITH(sim.run(), Catch::Contains("top.broken") && Catch::Contains(">= 0"));
}

TEST_CASE("atomic states are plain values that can be checkpointed and restored") {
  Coupled root("root");
  auto& gen = root.add<Emitter>("gen", std::vector<devs::Time>{1.0, 2.0});
  auto& col = root.add<Collector>("col");
  root.couple(gen.out, col.in);
  Simulator sim(root);
  sim.runUntil(1.5);
  const CollectorState checkpoint = col.state();
  sim.run();
  CHECK(col.state().bags.size() == 2);
  col.setState(checkpoint);
  CHECK(col.state().bags.size() == 1);
}

TEST_CASE("a simulator restored from a checkpoint goes on exactly as the one that wrote it") {
  // (gpt run to t = 7.25, archived) => a fresh model restored from it gives the same records
  GptParameters p;
  auto whole = makeGpt(p);
  Simulator a(*whole);
  RecordCollector recA;
  a.addListener(recA);
  a.runUntil(7.25);
  REQUIRE(a.firstUncheckpointable() == nullptr);
  devs::CheckpointWriter w;
  a.saveCheckpoint(w);
  const std::size_t before = recA.records.size();
  a.run();
  const std::vector<Record> after(recA.records.begin() + static_cast<std::ptrdiff_t>(before),
                                  recA.records.end());
  REQUIRE(!after.empty());

  auto fresh = makeGpt(p);
  Simulator b(*fresh);
  RecordCollector recB;
  b.addListener(recB);
  devs::CheckpointReader r(w.bytes());
  b.loadCheckpoint(r);
  CHECK(r.atEnd());
  CHECK(b.time() == 7.25);
  b.run();
  REQUIRE(recB.records.size() == after.size());
  for (std::size_t i = 0; i < after.size(); ++i) {
    CHECK(recB.records[i].t == after[i].t);
    CHECK(recB.records[i].model == after[i].model);
    CHECK(recB.records[i].kind == after[i].kind);
    CHECK(recB.records[i].port == after[i].port);
    CHECK(recB.records[i].value == after[i].value);
  }
  CHECK(b.stats().internal == a.stats().internal);
  CHECK(b.stats().messages == a.stats().messages);
}

TEST_CASE("a checkpoint is refused by another model, and a state without a codec is named") {
  GptParameters p;
  auto gpt = makeGpt(p);
  Simulator a(*gpt);
  a.runUntil(3.0);
  devs::CheckpointWriter w;
  a.saveCheckpoint(w);
  // (another hierarchy) => refused, naming a model that differs
  Coupled other("root");
  other.add<Emitter>("gen", std::vector<devs::Time>{1.0});
  Simulator b(other);
  devs::CheckpointReader r(w.bytes());
  CHECK_THROWS_AS(b.loadCheckpoint(r), devs::CheckpointError);
  // (a state type without a StateCodec) => named before anything is written
  REQUIRE(b.firstUncheckpointable() != nullptr);
  CHECK(b.firstUncheckpointable()->path() == "root.gen");
  devs::CheckpointWriter w2;
  CHECK_THROWS_WITH(b.saveCheckpoint(w2), Catch::Contains("'root.gen' cannot be checkpointed"));
}

namespace {
// An illegitimate model: it never lets time advance (time advance 0 after every transition).
struct Spin {
  std::uint64_t n = 0;
};
std::ostream& operator<<(std::ostream& os, const Spin& s) { return os << s.n; }
class Spinner final : public devs::Atomic<Spin> {
 public:
  explicit Spinner(std::string name) : devs::Atomic<Spin>(std::move(name), Spin{}) {}

 protected:
  devs::Time timeAdvance(const Spin& s) const override { return s.n < 3 ? 1.0 : 0.0; }
  void output(const Spin&) const override {}
  void internalTransition(Spin& s) const override { ++s.n; }
  void externalTransition(Spin&, devs::Time) const override {}
};
}  // namespace

TEST_CASE("a model that never lets time advance is stopped past the limit, naming it and the time") {
  Coupled root("root");
  root.add<Spinner>("spin");
  Simulator sim(root);
  sim.setInstantLimit(1000);
  try {
    sim.runUntil(100.0);
    FAIL("expected the zero-time loop to be stopped");
  } catch (const devs::SimulationError& e) {
    const std::string msg = e.what();
    CHECK(msg.find("more than 1000 transitions at t = 3") != std::string::npos);
    CHECK(msg.find("'root.spin'") != std::string::npos);
  }
  CHECK(sim.time() == 3.0);
  CHECK(sim.stats().internal == 2 + 1000);  // at t = 1 and 2, then 1000 at t = 3: the limit
  // (no limit) => the default simulator does not count (benchmarks pay nothing for it)
  Coupled other("other");
  other.add<Spinner>("spin");
  Simulator free(other);
  for (int i = 0; i < 5000; ++i) free.step();
  CHECK(free.time() == 3.0);
}
