#pragma once
// Argument checks of the kernel's algorithms (as Pinocchio's model.check(data)): a Data made for
// a model of another shape, or q, v, tau of the wrong size, is refused with a message naming the
// algorithm. The algorithms call them in debug builds only (YARDSIM_DYNAMICS_CHECK): a Release
// build pays nothing; callers at the door may call them in any build.
#include <string_view>

#include <Eigen/Core>

#include "dynamics/data.hpp"
#include "dynamics/model.hpp"

namespace yardsim::dynamics {

// (model, data) => whether data was made for a model of this shape (bodies, nq, nv, loop rows)
bool fits(const Model& model, const Data& data);

// (model, data, q, v or nullptr, ddq or tau or nullptr, algorithm) => throws
// std::invalid_argument naming the algorithm and what does not fit
void checkArguments(const Model& model, const Data& data, const Eigen::VectorXd& q,
                    const Eigen::VectorXd* v, const Eigen::VectorXd* nvSized, std::string_view who);

}  // namespace yardsim::dynamics

#ifndef NDEBUG
#define YARDSIM_DYNAMICS_CHECK(model, data, q, v, nvSized, who) \
  ::yardsim::dynamics::checkArguments(model, data, q, v, nvSized, who)
#else
#define YARDSIM_DYNAMICS_CHECK(model, data, q, v, nvSized, who) ((void)0)
#endif
