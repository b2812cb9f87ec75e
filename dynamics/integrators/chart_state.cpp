#include "dynamics/integrators/chart_state.hpp"

#include <algorithm>

#include "dynamics/configuration.hpp"

namespace yardsim::dynamics {

ChartState::ChartState(const Model& model)
    : model_(model), origin_(neutralConfiguration(model)), theta_(model.nv), v_(model.nv), rate_(model.nv) {}

void ChartState::gather(const Eigen::VectorXd& q, const Eigen::VectorXd& v, double* y) {
  origin_ = q;
  Eigen::Map<Eigen::VectorXd> Y(y, size());
  Y.head(model_.nv).setZero();
  Y.tail(model_.nv) = v;
}

void ChartState::scatter(const double* y, Eigen::VectorXd& q, Eigen::VectorXd& v) const {
  const Eigen::Map<const Eigen::VectorXd> Y(y, size());
  theta_ = Y.head(model_.nv);
  v = Y.tail(model_.nv);
  integrate(model_, origin_, theta_, 1.0, q);
}

void ChartState::kinematicRate(const double* y, double* ydot) const {
  const Eigen::Map<const Eigen::VectorXd> Y(y, size());
  theta_ = Y.head(model_.nv);
  v_ = Y.tail(model_.nv);
  chartRate(model_, theta_, v_, rate_);
  Eigen::Map<Eigen::VectorXd>(ydot, model_.nv) = rate_;
}

void ChartState::dynamicRate(const Eigen::VectorXd& a, double* ydot) const {
  Eigen::Map<Eigen::VectorXd>(ydot + model_.nv, model_.nv) = a;
}

double ChartState::rotationExtent(const double* y) const {
  double extent = 0.0;
  for (int i = 1; i < model_.nbodies; ++i) {
    const JointType t = model_.joints[i].type;
    if (t == JointType::Spherical || t == JointType::Free)
      extent = std::max(extent, Eigen::Map<const Eigen::Vector3d>(y + model_.idxV[i]).norm());
  }
  return extent;
}

}  // namespace yardsim::dynamics
