#include "dynamics/integrators/sundials_vector_pool.hpp"

#include <algorithm>
#include <cstdlib>
#include <new>

namespace yardsim::dynamics {

namespace {

// The content of the pool's vectors and their clones: the serial content first, which the serial
// operations and accessors (NV_CONTENT_S) read through a pointer to it.
struct PooledContent {
  _N_VectorContent_Serial serial;
  SundialsVectorPool* pool;
  bool member;  // one of the pool's own vectors: given back, not freed
};

PooledContent* contentOf(N_Vector v) {
  return static_cast<PooledContent*>(v->content);
}

// (w, the pool, member) => a vector with w's operations and an empty pooled content of w's
// length (N_VCloneEmpty_Serial's three blocks); nullptr when out of memory
N_Vector emptyLike(N_Vector w, SundialsVectorPool* pool, bool member) {
  N_Vector v = N_VNewEmpty(w->sunctx);
  if (v == nullptr) return nullptr;
  auto* c = static_cast<PooledContent*>(std::malloc(sizeof(PooledContent)));
  if (c == nullptr || N_VCopyOps(w, v) != 0) {
    std::free(c);
    N_VFreeEmpty(v);
    return nullptr;
  }
  *c = PooledContent{{NV_LENGTH_S(w), SUNFALSE, nullptr}, pool, member};
  v->content = c;
  return v;
}

// (w) => an empty clone: a free vector of w's pool, else a new one
N_Vector cloneEmpty(N_Vector w) {
  if (w == nullptr) return nullptr;
  SundialsVectorPool* pool = contentOf(w)->pool;
  if (N_Vector v = pool->take()) return v;
  pool->countAllocated();
  return emptyLike(w, pool, false);
}

// (w) => a clone owning its (uninitialised) data, as N_VClone_Serial's, with w's pool
N_Vector cloneVector(N_Vector w) {
  if (w == nullptr) return nullptr;
  N_Vector v = emptyLike(w, contentOf(w)->pool, false);
  if (v == nullptr) return nullptr;
  const sunindextype n = NV_LENGTH_S(w);
  if (n > 0) {
    auto* data =
        static_cast<realtype*>(std::malloc(static_cast<std::size_t>(n) * sizeof(realtype)));
    if (data == nullptr) {
      N_VDestroy_Serial(v);
      return nullptr;
    }
    NV_OWN_DATA_S(v) = SUNTRUE;
    NV_DATA_S(v) = data;
  }
  return v;
}

// (v) => one of the pool's vectors given back, any other freed as a serial vector
void destroyVector(N_Vector v) {
  if (v == nullptr) return;
  PooledContent* c = v->content != nullptr ? contentOf(v) : nullptr;
  if (c != nullptr && c->member) {
    c->pool->give(v);
    return;
  }
  N_VDestroy_Serial(v);
}

// (context, length, pool, member) => an empty serial vector with the pooled content and the three
// operations replaced
N_Vector makeEmpty(SUNContext ctx, sunindextype length, SundialsVectorPool* pool, bool member) {
  N_Vector v = N_VNewEmpty_Serial(length, ctx);  // the serial operations
  if (v == nullptr) throw std::bad_alloc();
  auto* c = static_cast<PooledContent*>(std::malloc(sizeof(PooledContent)));
  if (c == nullptr) {
    N_VDestroy_Serial(v);
    throw std::bad_alloc();
  }
  std::free(v->content);
  *c = PooledContent{{length, SUNFALSE, nullptr}, pool, member};
  v->content = c;
  v->ops->nvclone = cloneVector;
  v->ops->nvcloneempty = cloneEmpty;
  v->ops->nvdestroy = destroyVector;
  return v;
}

}  // namespace

SundialsVectorPool::SundialsVectorPool(SUNContext ctx, sunindextype length, int capacity)
    : ctx_(ctx), length_(length) {
  own_.reserve(static_cast<std::size_t>(capacity));
  free_.reserve(static_cast<std::size_t>(capacity));
  for (int k = 0; k < capacity; ++k) {
    own_.push_back(makeEmpty(ctx, length, this, true));
    free_.push_back(own_.back());
  }
}

SundialsVectorPool::~SundialsVectorPool() {
  // (its vectors) => the free ones freed; one still out is let go (its N_VDestroy frees it)
  for (N_Vector v : own_) {
    if (std::find(free_.begin(), free_.end(), v) != free_.end())
      N_VDestroy_Serial(v);
    else
      contentOf(v)->member = false;
  }
}

N_Vector SundialsVectorPool::makeVector() {
  N_Vector v = makeEmpty(ctx_, length_, this, false);
  if (length_ > 0) {
    const auto n = static_cast<std::size_t>(length_);
    auto* data = static_cast<realtype*>(std::malloc(n * sizeof(realtype)));
    if (data == nullptr) {
      N_VDestroy_Serial(v);
      throw std::bad_alloc();
    }
    std::fill(data, data + n, 0.0);
    NV_OWN_DATA_S(v) = SUNTRUE;
    NV_DATA_S(v) = data;
  }
  return v;
}

N_Vector SundialsVectorPool::take() {
  if (free_.empty()) return nullptr;
  N_Vector v = free_.back();
  free_.pop_back();
  ++served_;
  return v;
}

void SundialsVectorPool::give(N_Vector v) {
  if (NV_OWN_DATA_S(v) && NV_DATA_S(v) != nullptr) std::free(NV_DATA_S(v));
  NV_DATA_S(v) = nullptr;
  NV_OWN_DATA_S(v) = SUNFALSE;
  free_.push_back(v);
}

}  // namespace yardsim::dynamics
