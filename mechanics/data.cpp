#include "mechanics/data.hpp"

namespace yardsim::mechanics {

Data::Data(const System& s)
    : kernel(s.model()),
      scratch(s.model()),
      view(s.model()),
      feedforward(s.model()),
      reaction(s.model()),
      spForces(s.model()),
      spTau(Eigen::VectorXd::Zero(s.model().nv)),
      prescribedMask(static_cast<std::size_t>(s.model().nv), 0),
      prescribedAcc(Eigen::VectorXd::Zero(s.model().nv)),
      accelScratch(Eigen::VectorXd::Zero(s.model().nv)) {}

}  // namespace yardsim::mechanics
