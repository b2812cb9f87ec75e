#pragma once
// Operations on whole configurations q (size nq) with velocities v (size nv), joint by joint.

#include <Eigen/Core>
#include <random>

#include "dynamics/model.hpp"

namespace yardsim::dynamics {

/// (q, v, dt) => qOut = q (+) v dt (qOut may alias q).
void integrate(const Model& model, const Eigen::VectorXd& q, const Eigen::VectorXd& v, double dt, Eigen::VectorXd& qOut);
/// (q0, q1) => d (size nv) with integrate(q0, d, 1) = q1.
void difference(const Model& model, const Eigen::VectorXd& q0, const Eigen::VectorXd& q1, Eigen::VectorXd& d);
/// (theta, v) => dtheta/dt for q(t) = q0 (+) theta(t) moving with velocity v (the chart used by RK4).
void chartRate(const Model& model, const Eigen::VectorXd& theta, const Eigen::VectorXd& v, Eigen::VectorXd& thetaDot);
/// The configuration at rest: zero angles and displacements, identity quaternions.
Eigen::VectorXd neutralConfiguration(const Model& model);
/// (q) => q with every quaternion normalised.
void normalizeConfiguration(const Model& model, Eigen::VectorXd& q);
/// A random configuration: angles and displacements uniform in [-1, 1], uniform random quaternions.
Eigen::VectorXd randomConfiguration(const Model& model, std::mt19937& rng);

}  // namespace yardsim::dynamics
