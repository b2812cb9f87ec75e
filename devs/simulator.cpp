#include "devs/simulator.hpp"

#include <cmath>
#include <string>

namespace yardsim::devs {
namespace {
constexpr std::uint8_t kImminent = 1;
constexpr std::uint8_t kHasInput = 2;
}  // namespace

Simulator::Simulator(Model& root, Time t0) : flat_(flatten(root)), t_(t0) {
  const std::size_t n = flat_.atomics.size();
  queue_.resize(n);
  slots_.reserve(n);
  for (std::uint32_t i = 0; i < n; ++i)
    slots_.push_back({flat_.atomics[i], t0, flat_.outBegin[i], flat_.outBegin[i + 1]});
  flags_.assign(n, 0);
  imminent_.reserve(n);
  receivers_.reserve(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    flat_.atomics[i]->initialize(t0);
    reschedule(i, t0);
  }
}

void Simulator::addListener(Listener& listener) {
  listeners_.push_back(&listener);
}

namespace {
// (model, its next event time before t) => throws the SimulationError that names them; apart
// from reschedule, whose frame it would otherwise widen
[[noreturn, gnu::cold, gnu::noinline]] void throwTimeAdvance(const AtomicBase& a, Time tn, Time t) {
  throw SimulationError("model '" + a.path() + "' scheduled its next event at " +
                        std::to_string(tn) + " s, before the current time " + std::to_string(t) +
                        " s; a time advance must be >= 0 (or infinity)");
}
}  // namespace

void Simulator::reschedule(std::uint32_t i, Time t) {
  Slot& s = slots_[i];
  const Time tn = s.model->nextEventTime(t);
  if (!(tn >= t)) throwTimeAdvance(*s.model, tn, t);
  s.tl = t;
  queue_.schedule(i, tn);
}

void Simulator::start() {
  if (started_) return;
  started_ = true;
  for (Listener* l : listeners_) {
    l->onStart(t_, flat_.atomics);
    for (AtomicBase* a : flat_.atomics) l->onState(t_, *a);
  }
}

void Simulator::countInstant(Time t, std::size_t transitions) {
  // (steps at one time) => transitions since time last advanced; past the limit, the models
  atInstant_ = (t == lastInstant_ ? atInstant_ : 0) + transitions;
  lastInstant_ = t;
  if (atInstant_ <= instantLimit_) return;
  std::string who;
  std::size_t named = 0;
  for (const std::uint32_t i : imminent_) {
    if (named++ == 5) {
      who += ", ...";
      break;
    }
    who += (who.empty() ? "'" : ", '") + flat_.atomics[i]->path() + "'";
  }
  for (const std::uint32_t r : receivers_) {
    if (named++ >= 5) break;
    who += (who.empty() ? "'" : ", '") + flat_.atomics[r]->path() + "'";
  }
  throw SimulationError(
      "more than " + std::to_string(instantLimit_) + " transitions at t = " + std::to_string(t) +
      " s without time advancing: the models " + who +
      " keep scheduling events at the same time (a zero time advance in a loop); "
      "suggestion: give them a time advance > 0, or raise --max-transitions-per-instant");
}

bool Simulator::step() {
  start();
  if (queue_.empty()) return false;
  const Time t = queue_.topTime();
  t_ = t;
  const bool traced = !listeners_.empty();

  // (heap) => imminent atomics, removed from the heap
  imminent_.clear();
  while (!queue_.empty() && queue_.topTime() == t) {
    const std::uint32_t i = queue_.pop();
    imminent_.push_back(i);
    flags_[i] = kImminent;
  }

  // (imminent states) => output bags, copied along the flattened couplings
  receivers_.clear();
  filled_.clear();
  for (const std::uint32_t i : imminent_) {
    const Slot& s = slots_[i];
    AtomicBase* a = s.model;
    a->lambda();
    for (std::uint32_t j = s.outFirst; j < s.outLast; ++j) {
      const PortBase* out = flat_.outs[j].port;
      if (out->empty()) continue;
      const std::uint32_t first = flat_.outs[j].destFirst, last = flat_.outs[j].destLast;
      const std::span<PortBase* const> dsts(flat_.destPorts.data() + first, last - first);
      if (traced) {
        for (Listener* l : listeners_) l->onOutput(t, *a, *out);
        for (PortBase* p : dsts) {
          if (p->empty()) filled_.push_back(p);
          out->appendTo(*p);
        }
      } else {
        out->appendToEach(dsts);
      }
      stats_.messages += out->size() * dsts.size();
      for (std::uint32_t k = first; k < last; ++k) {
        const std::uint32_t r = flat_.destAtomics[k];
        if (!(flags_[r] & kHasInput)) {
          if (!(flags_[r] & kImminent)) receivers_.push_back(r);
          flags_[r] |= kHasInput;
        }
      }
    }
  }
  if (traced)
    for (PortBase* p : filled_)
      for (Listener* l : listeners_) l->onInput(t, static_cast<const AtomicBase&>(p->owner()), *p);

  // (inputs, states) => internal, confluent and external transitions; each atomic's bags
  // cleared and the atomic rescheduled right after its own transition (imminent ones first,
  // then receivers, each in order: the queue sees the same operations in the same order as
  // when all transitions come first), so an atomic is visited once here
  if (instantLimit_ > 0) countInstant(t, imminent_.size() + receivers_.size());
  for (const std::uint32_t i : imminent_) {
    const Slot& s = slots_[i];
    AtomicBase* a = s.model;
    const Time e = t - s.tl;
    Transition kind;
    const bool input = flags_[i] & kHasInput;
    if (input) {
      a->deltaConf(e);
      kind = Transition::Confluent;
      ++stats_.confluent;
    } else {
      a->deltaInt();
      kind = Transition::Internal;
      ++stats_.internal;
    }
    if (traced)
      for (Listener* l : listeners_) {
        l->onTransition(t, *a, kind, e);
        l->onState(t, *a);
      }
    for (std::uint32_t j = s.outFirst; j < s.outLast; ++j)
      if (!flat_.outs[j].port->empty()) flat_.outs[j].port->clear();
    if (input) clearInputs(*a);
    flags_[i] = 0;
    reschedule(i, t);
  }
  for (const std::uint32_t r : receivers_) {
    AtomicBase* a = slots_[r].model;
    const Time e = t - slots_[r].tl;
    a->deltaExt(e);
    ++stats_.external;
    if (traced)
      for (Listener* l : listeners_) {
        l->onTransition(t, *a, Transition::External, e);
        l->onState(t, *a);
      }
    clearInputs(*a);
    flags_[r] = 0;
    reschedule(r, t);
  }
  ++stats_.eventTimes;
  return true;
}

void Simulator::clearInputs(AtomicBase& a) {
  for (PortBase* p : a.inPorts())
    if (!p->empty()) p->clear();
}

const AtomicBase* Simulator::firstUncheckpointable() const {
  for (const AtomicBase* a : flat_.atomics)
    if (!a->canCheckpoint()) return a;
  return nullptr;
}

void Simulator::saveCheckpoint(CheckpointWriter& w) {
  // (simulator) => clock, counters, queue, then per atomic its path and state
  w.section("simulator");
  devs::save(w, t_);
  ListVector<Time> tl;  // the times of the last transitions, one list as the archive holds them
  tl.reserve(slots_.size());
  for (const Slot& s : slots_) tl.push_back(s.tl);
  devs::save(w, tl);
  for (const std::uint64_t c : {stats_.eventTimes, stats_.internal, stats_.external,
                                stats_.confluent, stats_.messages, atInstant_})
    w.i64(static_cast<std::int64_t>(c));
  devs::save(w, lastInstant_);
  queue_.save(w);
  w.list(flat_.atomics.size());
  for (const AtomicBase* a : flat_.atomics) {
    w.str(a->path());
    a->saveCheckpoint(w);
  }
  for (AtomicBase* a : flat_.atomics) a->afterCheckpoint();
}

void Simulator::loadCheckpoint(CheckpointReader& r) {
  r.section("simulator");
  devs::load(r, t_);
  ListVector<Time> tl;
  devs::load(r, tl);
  if (tl.size() != slots_.size())
    throw CheckpointError("the checkpoint holds " + std::to_string(tl.size()) +
                          " atomic models, this scene " + std::to_string(slots_.size()));
  for (std::size_t i = 0; i < tl.size(); ++i) slots_[i].tl = tl[i];
  for (std::uint64_t* c : {&stats_.eventTimes, &stats_.internal, &stats_.external,
                           &stats_.confluent, &stats_.messages, &atInstant_})
    *c = static_cast<std::uint64_t>(r.i64());
  devs::load(r, lastInstant_);
  queue_.load(r);
  if (r.list() != flat_.atomics.size())
    throw CheckpointError("the checkpoint's model list differs from this scene's");
  for (AtomicBase* a : flat_.atomics) {
    const std::string path = r.str();
    if (path != a->path())
      throw CheckpointError("the checkpoint holds model '" + path + "' where this scene has '" +
                            a->path() + "'");
    a->loadCheckpoint(r);
  }
  // (restored run) => listeners told of the start, without the initial states
  started_ = true;
  for (Listener* l : listeners_) l->onStart(t_, flat_.atomics);
}

void Simulator::runUntil(Time tEnd) {
  start();
  while (!queue_.empty() && queue_.topTime() <= tEnd) step();
  if (tEnd != kInfinity && tEnd > t_) t_ = tEnd;
  notifyEnd();
}

void Simulator::notifyEnd() {
  for (Listener* l : listeners_) l->onEnd(t_);
}

}  // namespace yardsim::devs
