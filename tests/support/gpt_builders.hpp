#pragma once
// Test support: the generator-processor-transducer model built in C++, as a three-level
// hierarchy and as its flat equivalent, from the scene library's types.
#include <memory>

#include "devs/coupled.hpp"
#include "models/library/gpt.hpp"

namespace yardsim::testing {

struct GptParameters {
  devs::Time period = 1.0;
  devs::Time processing = 1.5;
  devs::Time observe = 20.0;
};

// (parameters) => gpt = { ef = { genr, transd }, proc }
inline std::unique_ptr<devs::Coupled> makeGpt(const GptParameters& p) {
  using namespace models::library;
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

// (parameters) => the same atomics in one coupled model with direct couplings
inline std::unique_ptr<devs::Coupled> makeFlatGpt(const GptParameters& p) {
  using namespace models::library;
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

}  // namespace yardsim::testing
