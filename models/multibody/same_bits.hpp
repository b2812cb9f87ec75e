#pragma once
// Bit-for-bit equality of two state vectors, for the multibody model's caches of the committed
// state (a -0.0 and a 0.0 differ, a NaN equals itself: the same doubles give the same results).
#include <Eigen/Core>

namespace yardsim::models {

// (a, b) => the same size and every coefficient the same bits
bool sameBits(const Eigen::VectorXd& a, const Eigen::VectorXd& b);

}  // namespace yardsim::models
