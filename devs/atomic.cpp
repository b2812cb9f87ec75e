#include "devs/atomic.hpp"

namespace yardsim::devs {
namespace {
// (model) => the refusal of a model whose state cannot be archived
CheckpointError noCodec(const AtomicBase& m) {
  return CheckpointError("model '" + m.path() +
                         "' cannot be checkpointed: its state type has no StateCodec "
                         "(docs/extending.md, checkpoints)");
}
}  // namespace

void AtomicBase::saveCheckpoint(CheckpointWriter& /*w*/) const {
  throw noCodec(*this);
}

void AtomicBase::loadCheckpoint(CheckpointReader& /*r*/) {
  throw noCodec(*this);
}

}  // namespace yardsim::devs
