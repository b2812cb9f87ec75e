#include "dynamics/integrators/hht.hpp"

namespace yardsim::dynamics {

GeneralizedAlphaParameters hhtParameters(double alpha) {
  GeneralizedAlphaParameters p;
  p.alphaM = 0.0;
  p.alphaF = -alpha;
  p.gamma = 0.5 - alpha;
  p.beta = 0.25 * (1.0 - alpha) * (1.0 - alpha);
  return p;
}

}  // namespace yardsim::dynamics
