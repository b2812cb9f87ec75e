#include "dynamics/checks.hpp"

#include <stdexcept>
#include <string>

namespace yardsim::dynamics {

bool fits(const Model& m, const Data& d) {
  const auto nb = static_cast<std::size_t>(m.nbodies);
  return d.X_WB.size() == nb && d.V_B.size() == nb && d.IA_W.size() == nb && d.tau.size() == m.nv &&
         d.ddq.size() == m.nv && d.M.rows() == m.nv && d.dq.size() == m.nq &&
         d.residual.size() == m.nc && d.J.cols() == m.nv;
}

void checkArguments(const Model& m, const Data& d, const Eigen::VectorXd& q,
                    const Eigen::VectorXd* v, const Eigen::VectorXd* nvSized,
                    std::string_view who) {
  // (sizes) => the first that does not fit, named
  auto refuse = [&](const std::string& what) {
    throw std::invalid_argument("yardsim::dynamics::" + std::string(who) + ": " + what);
  };
  if (!fits(m, d)) refuse("the Data was made for another model (another number of bodies or dofs)");
  if (q.size() != m.nq)
    refuse("q has " + std::to_string(q.size()) + " values, the model nq = " + std::to_string(m.nq));
  if (v && v->size() != m.nv)
    refuse("v has " + std::to_string(v->size()) +
           " values, the model nv = " + std::to_string(m.nv));
  if (nvSized && nvSized->size() != m.nv)
    refuse("a joint-space vector (ddq or tau) has " + std::to_string(nvSized->size()) +
           " values, the model nv = " + std::to_string(m.nv));
}

}  // namespace yardsim::dynamics
