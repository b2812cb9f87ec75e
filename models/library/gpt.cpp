#include "models/library/gpt.hpp"

#include "models/registry.hpp"

namespace yardsim::models::library {

std::ostream& operator<<(std::ostream& os, const GeneratorState& s) {
  return os << "next=" << s.next << (s.active ? " active" : " stopped");
}
std::ostream& operator<<(std::ostream& os, const ProcessorState& s) {
  return os << (s.job ? "busy job=" + std::to_string(s.job) : std::string("idle"));
}
std::ostream& operator<<(std::ostream& os, const TransducerState& s) {
  return os << "arrived=" << s.arrived << " solved=" << s.solved;
}

Generator::Generator(std::string name, Time period)
    : devs::Atomic<GeneratorState>(std::move(name), GeneratorState{}), period_(period) {}

Time Generator::timeAdvance(const GeneratorState& s) const {
  return s.active ? s.sigma : devs::kInfinity;
}
void Generator::output(const GeneratorState& s) const { out.add(s.next); }
void Generator::internalTransition(GeneratorState& s) const {
  ++s.next;
  s.sigma = period_;
}
void Generator::externalTransition(GeneratorState& s, Time e) const {
  s.sigma -= e;
  if (!stop.values().empty()) s.active = false;
}

Processor::Processor(std::string name, Time processing)
    : devs::Atomic<ProcessorState>(std::move(name), ProcessorState{}), processing_(processing) {}

void Processor::output(const ProcessorState& s) const { out.add(s.job); }
void Processor::internalTransition(ProcessorState& s) const {
  s.job = 0;
  s.sigma = devs::kInfinity;
}
void Processor::externalTransition(ProcessorState& s, Time e) const {
  if (s.job != 0) {  // busy: the new job is lost
    s.sigma -= e;
    return;
  }
  s.job = in.values().front();
  s.sigma = processing_;
}

Transducer::Transducer(std::string name, Time observe)
    : devs::Atomic<TransducerState>(std::move(name), TransducerState{0.0, observe, 0, 0, 0.0, {}}) {}

double Transducer::throughput() const {
  return state().clock > 0 ? state().solved / state().clock : 0.0;
}
double Transducer::meanTurnaround() const {
  return state().solved ? state().turnaroundSum / state().solved : 0.0;
}
void Transducer::output(const TransducerState&) const { stop.add(true); }
void Transducer::internalTransition(TransducerState& s) const {
  s.clock += s.sigma;
  s.sigma = devs::kInfinity;
}
void Transducer::externalTransition(TransducerState& s, Time e) const {
  if (s.sigma == devs::kInfinity) return;  // observation over: late jobs are not counted
  s.clock += e;
  s.sigma -= e;
  for (int id : arrived.values()) {
    ++s.arrived;
    if (static_cast<std::size_t>(id) > s.arrivals.size()) s.arrivals.resize(id, 0.0);
    s.arrivals[id - 1] = s.clock;
  }
  for (int id : solved.values()) {
    ++s.solved;
    s.turnaroundSum += s.clock - s.arrivals.at(id - 1);
  }
}

void Generator::channels(std::vector<Channel>& c) const {
  c.push_back({"emitted", "-", [this] { return static_cast<double>(state().next - 1); }});
}
void Processor::channels(std::vector<Channel>& c) const {
  c.push_back({"busy", "-", [this] { return state().job != 0 ? 1.0 : 0.0; }});
}
void Transducer::channels(std::vector<Channel>& c) const {
  c.push_back({"arrived", "-", [this] { return static_cast<double>(state().arrived); }});
  c.push_back({"solved", "-", [this] { return static_cast<double>(state().solved); }});
  c.push_back({"throughput", "1/s", [this] { return throughput(); }});
}

namespace {
ParamSpec seconds(const char* name, const char* doc) {
  return {name, ParamKind::Number, true, "", "s", doc};
}
void positive(const Params& p, ParamCheck& check, const char* name, bool zeroOk) {
  const double v = p.number(name);
  if (zeroOk ? v < 0.0 : !(v > 0.0))
    check.error(name, std::string("must be ") + (zeroOk ? ">= 0" : "> 0") + " s, got " +
                          std::to_string(v));
}
}  // namespace

YARDSIM_REGISTER_TYPE(generator, TypeInfo{
    .name = "generator",
    .summary = "emits job ids 1, 2, ... every `period` seconds until it receives `stop`",
    .params = {seconds("period", "time between jobs")},
    .ports = [](const Params&) {
      return std::vector<PortSpec>{{"stop", "bool", true}, {"out", "int", false}};
    },
    .create = [](const std::string& n, const Params& p) -> std::unique_ptr<devs::AtomicBase> {
      return std::make_unique<Generator>(n, p.number("period"));
    },
    .check = [](const Params& p, ParamCheck& c) { positive(p, c, "period", false); },
    .feedthrough = {}});

YARDSIM_REGISTER_TYPE(processor, TypeInfo{
    .name = "processor",
    .summary = "serves one job at a time for `processing_time` seconds; jobs arriving while busy are lost",
    .params = {seconds("processing_time", "service time per job")},
    .ports = [](const Params&) {
      return std::vector<PortSpec>{{"in", "int", true}, {"out", "int", false}};
    },
    .create = [](const std::string& n, const Params& p) -> std::unique_ptr<devs::AtomicBase> {
      return std::make_unique<Processor>(n, p.number("processing_time"));
    },
    .check = [](const Params& p, ParamCheck& c) { positive(p, c, "processing_time", true); },
    .feedthrough = [](const Params& p) { return p.number("processing_time") == 0.0; }});

YARDSIM_REGISTER_TYPE(transducer, TypeInfo{
    .name = "transducer",
    .summary = "counts arrived and solved jobs for `observe` seconds, then sends `stop`",
    .params = {seconds("observe", "observation time")},
    .ports = [](const Params&) {
      return std::vector<PortSpec>{
          {"arrived", "int", true}, {"solved", "int", true}, {"stop", "bool", false}};
    },
    .create = [](const std::string& n, const Params& p) -> std::unique_ptr<devs::AtomicBase> {
      return std::make_unique<Transducer>(n, p.number("observe"));
    },
    .check = [](const Params& p, ParamCheck& c) { positive(p, c, "observe", false); },
    .feedthrough = {}});

}  // namespace yardsim::models::library
