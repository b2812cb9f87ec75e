#include "dtss/atomic.hpp"

#include <yaml-cpp/yaml.h>
#include <catch2/catch.hpp>
#include <charconv>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "devs/chrome_trace_sink.hpp"
#include "devs/coupled.hpp"
#include "devs/simulator.hpp"
#include "support/record_collector.hpp"
#include "support/test_models.hpp"

using namespace yardsim;
using devs::Time;
using dtss::Crossing;

namespace {

// A ball falling under gravity onto the ground, bouncing with restitution e. The step is
// the exact ballistic solution, so the located impact times can be checked in closed form.
struct Ball {
  double y, v;
};
std::ostream& operator<<(std::ostream& os, const Ball& b) { return os << b.y << "," << b.v; }

constexpr double kG = 9.81;

class BouncingBall final : public dtss::Atomic<Ball> {
 public:
  BouncingBall(double y0, double restitution, Time h, Time tol)
      : dtss::Atomic<Ball>("ball", Ball{y0, 0.0}, h, 0.0, tol), e_(restitution) {}
  devs::OutPort<double>& bounce = addOutPort<double>("bounce");

 protected:
  void advance(Ball& b, Time, Time dt) const override {
    b.y += b.v * dt - 0.5 * kG * dt * dt;
    b.v -= kG * dt;
  }
  std::span<const Crossing> eventDirections() const override { return dirs_; }
  void eventFunctions(const Ball& b, Time, std::span<double> g) const override { g[0] = b.y; }
  void outputAt(const Ball& b, Time, const dtss::Reached& r) const override {
    if (r.stateEvent == 0) bounce.add(b.v);
  }
  void onStateEvent(Ball& b, Time, int) const override { b.v = -e_ * b.v; }

 private:
  double e_;
  std::array<Crossing, 1> dirs_{Crossing::Falling};
};

// x' = 1 (a clock); inputs add 100 to x; lands on a user schedule of time events.
struct ClockState {
  double x = 0.0;
  int timeEvents = 0;  // reactions to time events
  std::vector<std::pair<Time, double>> inputs;  // (t, x after the input)
};
std::ostream& operator<<(std::ostream& os, const ClockState& s) { return os << s.x; }

class Clock final : public dtss::Atomic<ClockState> {
 public:
  Clock(Time h, std::vector<Time> schedule)
      : dtss::Atomic<ClockState>("clock", ClockState{}, h), schedule_(std::move(schedule)) {}
  devs::InPort<int>& in = addInPort<int>("in");
  devs::OutPort<double>& tick = addOutPort<double>("tick");
  devs::OutPort<double>& step = addOutPort<double>("step");

 protected:
  void advance(ClockState& s, Time, Time dt) const override { s.x += dt; }
  void applyInput(ClockState& s, Time t) const override {
    s.x += 100.0 * static_cast<double>(in.values().size());
    s.inputs.push_back({t, s.x});
  }
  Time nextTimeEvent(const ClockState&, Time t) const override {
    for (Time te : schedule_)
      if (te > t) return te;
    return devs::kInfinity;
  }
  void onTimeEvent(ClockState& s, Time) const override { ++s.timeEvents; }
  void outputAt(const ClockState& s, Time, const dtss::Reached& r) const override {
    if (r.timeEvent) tick.add(s.x);
    if (r.grid) step.add(s.x);
  }

 private:
  std::vector<Time> schedule_;
};

std::vector<double> times(const std::vector<testing::Record>& records, const std::string& port) {
  std::vector<double> out;
  for (const auto& r : records)
    if (r.kind == "out" && r.port == port) out.push_back(r.t);
  return out;
}

}  // namespace

TEST_CASE("a bouncing ball's impacts are located at the closed-form times") {
  const double y0 = 10.0, e = 0.8, tol = 1e-11;
  devs::Coupled root("root");
  auto& ball = root.add<BouncingBall>(y0, e, 0.1, tol);
  devs::Simulator sim(root);
  testing::RecordCollector rec(false);
  sim.addListener(rec);
  sim.runUntil(8.0);

  const auto impacts = times(rec.records, "bounce");
  REQUIRE(impacts.size() >= 4);
  // t1 = sqrt(2 y0 / g); then each flight lasts 2 e^k v1 / g
  const double v1 = std::sqrt(2.0 * kG * y0);
  double expected = v1 / kG;
  for (std::size_t k = 0; k < 4; ++k) {
    INFO("impact " << k);
    CHECK(impacts[k] == Approx(expected).margin(1e-8));
    expected += 2.0 * std::pow(e, static_cast<double>(k + 1)) * v1 / kG;
  }
  // the impact speed is reported at the located time, and it never tunnels below ground
  const auto outs = rec.ofKind("out");
  CHECK(YAML::Load(outs.front().value).as<double>() == Approx(-v1).epsilon(1e-8));
  CHECK(ball.state().x.y > -1e-6);
}

TEST_CASE("a clock's time events land exactly on user-given times and the grid is kept") {
  const std::vector<Time> schedule{0.35, 0.7, 1.0, 2.123456789};
  devs::Coupled root("root");
  root.add<Clock>(0.1, schedule);
  devs::Simulator sim(root);
  testing::RecordCollector rec(false);
  sim.addListener(rec);
  sim.runUntil(3.05);

  CHECK(times(rec.records, "tick") == schedule);  // exactly, not approximately
  const auto& clock = static_cast<const Clock&>(*root.findComponent("clock"));
  CHECK(clock.state().x.timeEvents == 4);  // the model reacted to each of them once
  const dtss::Grid grid{0.0, 0.1};
  const auto steps = times(rec.records, "step");
  REQUIRE(steps.size() == 30);
  for (std::size_t k = 0; k < steps.size(); ++k) CHECK(steps[k] == grid.at(std::int64_t(k) + 1));
  // x integrates x' = 1: its value at each tick is that time
  for (const auto& r : rec.ofKind("out"))
    CHECK(YAML::Load(r.value).as<double>() == Approx(r.t).margin(1e-12));
}

TEST_CASE("external events between steps are applied at their exact time") {
  devs::Coupled root("root");
  auto& gen = root.add<testing::Emitter>("gen", std::vector<Time>{0.25, 0.5, 0.625});
  auto& clock = root.add<Clock>(0.1, std::vector<Time>{});
  root.couple(gen.out, clock.in);
  devs::Simulator sim(root);
  testing::RecordCollector rec(false);
  sim.addListener(rec);
  sim.runUntil(1.0);

  const auto& inputs = clock.state().x.inputs;
  REQUIRE(inputs.size() == 3);
  CHECK(inputs[0].first == 0.25);
  CHECK(inputs[0].second == Approx(0.25 + 100.0).epsilon(1e-14));
  CHECK(inputs[1].first == 0.5);  // on a grid point: the step is committed, then the input
  CHECK(inputs[1].second == Approx(0.5 + 200.0).epsilon(1e-14));
  CHECK(inputs[2].first == 0.625);
  CHECK(inputs[2].second == Approx(0.625 + 300.0).epsilon(1e-14));
  // the grid is not shifted by the inputs: steps still land on k h
  const auto steps = times(rec.records, "step");
  REQUIRE(steps.size() == 10);
  for (std::size_t k = 0; k < steps.size(); ++k)
    CHECK(steps[k] == dtss::Grid{0.0, 0.1}.at(std::int64_t(k) + 1));
  CHECK(clock.state().x.x == Approx(1.0 + 300.0).epsilon(1e-14));
  CHECK(sim.stats().confluent == 1);
}

TEST_CASE("DTSS steps are spans in the Chrome trace") {
  devs::Coupled root("root");
  root.add<Clock>(0.25, std::vector<Time>{});
  devs::Simulator sim(root);
  std::ostringstream text;
  {
    devs::ChromeTraceSink chrome{devs::TraceStream(text)};
    sim.addListener(chrome);
    sim.runUntil(2.0);
  }
  int spans = 0;
  for (const auto& ev : YAML::Load(text.str())["traceEvents"]) {
    if (ev["ph"].as<std::string>() != "X") continue;
    ++spans;
    CHECK(ev["dur"].as<double>() == Approx(0.25e6));
    CHECK(ev["name"].as<std::string>() == "step");
  }
  CHECK(spans == 8);
}

TEST_CASE("each DTSS span starts where its step starts and lasts as long, number for number") {
  // time events between grid points at irregular offsets: more step lengths than the sink keeps
  // texts of (four), each coming back now and then
  std::vector<Time> schedule;
  const double offsets[] = {0.01, 0.02, 0.03, 0.05, 0.07, 0.011, 0.013};
  for (int k = 0; k < 60; ++k) schedule.push_back(0.1 * k + offsets[k % 7]);
  devs::Coupled root("root");
  root.add<Clock>(0.1, schedule);
  devs::Simulator sim(root);
  std::ostringstream text;
  testing::RecordCollector rec(false);
  {
    devs::ChromeTraceSink chrome{devs::TraceStream(text)};
    sim.addListener(chrome);
    sim.addListener(rec);
    sim.runUntil(6.0);
  }
  // (value) => std::to_chars' shortest text: what the trace writes
  const auto shortest = [](double v) {
    char buf[64];
    return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
  };
  // (the clock's transitions, each from the one before) => the spans expected, in order
  std::vector<std::pair<std::string, std::string>> expected;
  std::set<std::string> lengths;
  Time previous = 0.0;
  for (const auto& r : rec.records) {
    if (r.kind != "int" && r.kind != "conf") continue;
    const Time e = r.t - previous;
    previous = r.t;
    if (e <= 0.0) continue;
    expected.emplace_back(shortest((r.t - e) * 1e6), shortest(e * 1e6));
    lengths.insert(expected.back().second);
  }
  std::vector<std::pair<std::string, std::string>> spans;
  for (const auto& ev : YAML::Load(text.str())["traceEvents"])
    if (ev["ph"].as<std::string>() == "X")
      spans.emplace_back(ev["ts"].as<std::string>(), ev["dur"].as<std::string>());
  CHECK(expected.size() > 100);
  CHECK(lengths.size() > 8);
  CHECK(spans == expected);
}

TEST_CASE("a non-positive step is refused") {
  CHECK_THROWS_WITH(Clock(0.0, {}), Catch::Contains("clock") && Catch::Contains("h must be > 0"));
}

namespace {
// A stone falling through two gates at the same height (g0 = y, g1 = 2 y): both are crossed at
// the same instant; neither may be lost. It keeps falling (the gates only count).
struct Stone {
  double y, v;
  int reactions = 0;
};
std::ostream& operator<<(std::ostream& os, const Stone& s) { return os << s.y; }

class TwoGates final : public dtss::Atomic<Stone> {
 public:
  explicit TwoGates(double y0) : dtss::Atomic<Stone>("stone", Stone{y0, 0.0}, 0.1, 0.0, 1e-11) {}
  devs::OutPort<int>& gate = addOutPort<int>("gate");

 protected:
  void advance(Stone& s, Time, Time dt) const override {
    s.y += s.v * dt - 0.5 * kG * dt * dt;
    s.v -= kG * dt;
  }
  std::span<const Crossing> eventDirections() const override { return dirs_; }
  void eventFunctions(const Stone& s, Time, std::span<double> g) const override {
    g[0] = s.y;
    g[1] = 2.0 * s.y;
  }
  void outputAt(const Stone&, Time, const dtss::Reached& r) const override {
    if (r.stateEvent >= 0) gate.add(r.stateEvent);
    for (int j : r.coincident) gate.add(j);
  }
  void onStateEvent(Stone& s, Time, int) const override { ++s.reactions; }

 private:
  std::array<Crossing, 2> dirs_{Crossing::Falling, Crossing::Falling};
};
}  // namespace

TEST_CASE("two state events crossed at the same instant are both reached, reported and reacted to") {
  devs::Coupled root("root");
  auto& stone = root.add<TwoGates>(10.0);
  devs::Simulator sim(root);
  testing::RecordCollector rec(false);
  sim.addListener(rec);
  sim.runUntil(2.0);
  const auto gates = times(rec.records, "gate");
  REQUIRE(gates.size() == 2);
  CHECK(gates[0] == Approx(std::sqrt(2.0 * 10.0 / kG)).margin(1e-9));
  CHECK(gates[1] == gates[0]);
  CHECK(stone.state().x.reactions == 2);
}

TEST_CASE("the step count counts grid steps only, with time and state events between grid points") {
  // (time events at 0.35 and 0.7, off the grid, and 1.0, on it) => 30 grid steps up to 3.05 s
  devs::Coupled clocks("clocks");
  auto& clock = clocks.add<Clock>(0.1, std::vector<Time>{0.35, 0.7, 1.0});
  devs::Simulator a(clocks);
  a.runUntil(3.05);
  CHECK(clock.state().steps == 30);
  // (a bouncing ball: every impact is a located state event between grid points) => floor(T/h)
  devs::Coupled balls("balls");
  auto& ball = balls.add<BouncingBall>(10.0, 0.8, 0.1, 1e-11);
  devs::Simulator b(balls);
  testing::RecordCollector rec(false);
  b.addListener(rec);
  b.runUntil(8.05);
  REQUIRE(times(rec.records, "bounce").size() >= 4);
  CHECK(ball.state().steps == 80);
}

TEST_CASE("two DTSS models' steps, interleaved, each on its own track with its own length") {
  // (balls stepping at 0.1 s and 0.03 s, no output before their first impact at 1.43 s) => the
  // Chrome trace's steps alternate between the models with nothing between them: each span on its
  // model's track, as long as its model's step
  devs::Coupled root("root");
  root.add<devs::Coupled>("a").add<BouncingBall>(10.0, 0.8, 0.1, 1e-11);
  root.add<devs::Coupled>("b").add<BouncingBall>(10.0, 0.8, 0.03, 1e-11);
  devs::Simulator sim(root);
  std::ostringstream text;
  {
    devs::ChromeTraceSink chrome{devs::TraceStream(text)};
    sim.addListener(chrome);
    sim.runUntil(0.95);
  }
  const YAML::Node events = YAML::Load(text.str())["traceEvents"];
  std::map<int, std::string> track;  // tid => the model's path, from the tracks' names
  for (const auto& ev : events)
    if (ev["ph"].as<std::string>() == "M")
      track[ev["tid"].as<int>()] = ev["args"]["name"].as<std::string>();
  const std::map<std::string, double> step = {{"root.a.ball", 0.1}, {"root.b.ball", 0.03}};
  std::map<std::string, int> spans;
  for (const auto& ev : events) {
    if (ev["ph"].as<std::string>() != "X") continue;
    const std::string& model = track.at(ev["tid"].as<int>());
    ++spans[model];
    CHECK(ev["dur"].as<double>() == Approx(step.at(model) * 1e6));
  }
  CHECK(spans["root.a.ball"] == 9);   // 0.1 ... 0.9 s
  CHECK(spans["root.b.ball"] == 31);  // 0.03 ... 0.93 s
}
