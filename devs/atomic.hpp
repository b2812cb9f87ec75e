#pragma once
// Parallel DEVS atomic models (Chow & Zeigler). AtomicBase is what the Simulator drives;
// Atomic<S> is what a user derives from: its state S is a plain value type, kept apart from
// the behaviour (const member functions over S), so it can be copied as a checkpoint and
// printed into a trace.
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>

#include "devs/checkpoint_archive.hpp"
#include "devs/model.hpp"
#include "devs/time.hpp"

namespace yardsim::devs {

struct FlatModel;
class Model;
FlatModel flatten(Model& root);

enum class Transition : std::uint8_t { Internal, External, Confluent };

class AtomicBase : public Model {
 public:
  using Model::Model;
  bool isAtomic() const final { return true; }

  // Engine-facing interface, called by the Simulator only.
  // () => time until the next internal event (>= 0, kInfinity when passive)
  virtual Time ta() const = 0;
  // (time of the last transition) => absolute time of the next internal event. The default is
  // tl + ta(); a model that knows its next event time exactly (a discrete-time grid, a user
  // schedule) overrides it so that no rounding of tl + (tn - tl) moves the event.
  virtual Time nextEventTime(Time tl) const { return tl + ta(); }
  // () => messages added to output ports (the bag of this event time)
  virtual void lambda() = 0;
  // () => state after an internal event
  virtual void deltaInt() = 0;
  // (elapsed e since the last transition, input bags) => state after an external event
  virtual void deltaExt(Time e) = 0;
  // (e, input bags) => state when internal and external events fall at the same time
  virtual void deltaConf(Time e) = 0;
  // (simulation start time) => ready to run; called once before the first event
  virtual void initialize(Time /*t0*/) {}
  // () => the state as one JSON value, appended to out (trace "state" records)
  virtual void writeState(std::string& out) const { out += "null"; }
  // () => "devs", or "dtss" for discrete-time models (the Chrome trace draws their steps as spans)
  virtual std::string_view kind() const { return "devs"; }

  // Checkpoints (docs/scenes.md): only between event times.
  // () => whether the state can be archived (its type has a StateCodec)
  virtual bool canCheckpoint() const { return false; }
  // (archive) => the state, and whatever else the results depend on, appended
  virtual void saveCheckpoint(CheckpointWriter& w) const;
  // (archive at this model's record) => the state and the rest restored exactly
  virtual void loadCheckpoint(CheckpointReader& r);
  // () => a checkpoint was just written: what could not be archived (an adaptive integrator's
  // history) restarts here, so that the run goes on exactly as a restart from it would
  virtual void afterCheckpoint() {}

  // Index in the Simulator's flat list of atomics (set when flattened).
  std::uint32_t simIndex() const { return simIndex_; }

 private:
  friend FlatModel flatten(Model& root);
  std::uint32_t simIndex_ = 0;
};

template <class S>
class Atomic : public AtomicBase {
 public:
  using State = S;
  Atomic(std::string name, S initial) : AtomicBase(std::move(name)), state_(std::move(initial)) {}

  const S& state() const { return state_; }
  // (state) => replaces the current state (restoring a checkpoint); only between events
  void setState(S s) { state_ = std::move(s); }

  void writeState(std::string& out) const override { TraceFormat<S>::write(out, state_); }
  // (tl) => tl + timeAdvance(state), without going through ta()
  Time nextEventTime(Time tl) const override { return tl + timeAdvance(state_); }

  bool canCheckpoint() const override { return HasStateCodec<S>; }
  void saveCheckpoint(CheckpointWriter& w) const override {
    if constexpr (HasStateCodec<S>) {
      devs::save(w, state_);
      saveWorkspace(w);
    } else {
      AtomicBase::saveCheckpoint(w);
    }
  }
  void loadCheckpoint(CheckpointReader& r) override {
    if constexpr (HasStateCodec<S>) {
      devs::load(r, state_);
      loadWorkspace(r);
    } else {
      AtomicBase::loadCheckpoint(r);
    }
  }

 protected:
  // What a model defines: time advance, output, and the transitions, as functions of S.
  virtual Time timeAdvance(const S& s) const = 0;
  virtual void output(const S& s) const = 0;
  virtual void internalTransition(S& s) const = 0;
  virtual void externalTransition(S& s, Time e) const = 0;
  // (initialize only) => the state, for models that must set it up at the start time
  S& mutableState() { return state_; }
  // (archive) => what besides the state the results depend on (a cache the next step reuses);
  // (archive) => it restored. Both default to nothing.
  virtual void saveWorkspace(CheckpointWriter& /*w*/) const {}
  virtual void loadWorkspace(CheckpointReader& /*r*/) {}
  // Default confluent rule: internal first, then external with e = 0.
  virtual void confluentTransition(S& s, Time e) const {
    (void)e;
    internalTransition(s);
    externalTransition(s, 0.0);
  }

 private:
  Time ta() const final { return timeAdvance(state_); }
  void lambda() final { output(state_); }
  void deltaInt() final { internalTransition(state_); }
  void deltaExt(Time e) final { externalTransition(state_, e); }
  void deltaConf(Time e) final { confluentTransition(state_, e); }

  S state_;
};

}  // namespace yardsim::devs
