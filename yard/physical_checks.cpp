#include "yard/physical_checks.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <sstream>

#include "yard/database.hpp"

namespace yardsim::yard {

void checkMass(double mass, const std::string& what) {
  if (!std::isfinite(mass) || !(mass > 0))
    throw DatabaseError(what + ": the mass must be a finite number > 0 kg, got " +
                        std::to_string(mass));
}

void checkInertia(const dynamics::Matrix3& inertia, const std::string& what) {
  if (!inertia.allFinite()) throw DatabaseError(what + ": the inertia has a non-finite entry");
  const double scale = inertia.cwiseAbs().maxCoeff();
  if ((inertia - inertia.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale)
    throw DatabaseError(what + ": the inertia is not symmetric");
  const Eigen::SelfAdjointEigenSolver<dynamics::Matrix3> eig(inertia);
  const dynamics::Vector3 p = eig.eigenvalues();  // ascending
  std::ostringstream moments;
  moments.precision(6);
  moments << "principal moments " << p[0] << ", " << p[1] << ", " << p[2] << " kg m^2";
  if (!(p[0] > 1e-12 * scale) || !(scale > 0))
    throw DatabaseError(what + ": the inertia is not positive definite (" + moments.str() + ")");
  if (p[2] > (p[0] + p[1]) * (1 + 1e-9))
    throw DatabaseError(
        what +
        ": the inertia is not physical: the largest principal moment exceeds the sum of "
        "the other two (" +
        moments.str() + ")");
}

}  // namespace yardsim::yard
