#include "gpt_models.hpp"

namespace yardsim::examples::gpt {

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

std::unique_ptr<devs::Coupled> makeGpt(const Parameters& p) {
  auto gpt = std::make_unique<devs::Coupled>("gpt");
  auto& ef = gpt->add<devs::Coupled>("ef");
  auto& efIn = ef.addInPort<int>("in");
  auto& efOut = ef.addOutPort<int>("out");
  auto& genr = ef.add<Generator>("genr", p.period);
  auto& transd = ef.add<Transducer>("transd", p.observe);
  ef.couple(genr.out, efOut);
  ef.couple(genr.out, transd.arrived);
  ef.couple(efIn, transd.solved);
  ef.couple(transd.stop, genr.stop);
  auto& proc = gpt->add<Processor>("proc", p.processing);
  gpt->couple(efOut, proc.in);
  gpt->couple(proc.out, efIn);
  return gpt;
}

std::unique_ptr<devs::Coupled> makeFlatGpt(const Parameters& p) {
  auto gpt = std::make_unique<devs::Coupled>("gpt");
  auto& genr = gpt->add<Generator>("genr", p.period);
  auto& transd = gpt->add<Transducer>("transd", p.observe);
  auto& proc = gpt->add<Processor>("proc", p.processing);
  gpt->couple(genr.out, proc.in);
  gpt->couple(genr.out, transd.arrived);
  gpt->couple(proc.out, transd.solved);
  gpt->couple(transd.stop, genr.stop);
  return gpt;
}

}  // namespace yardsim::examples::gpt
