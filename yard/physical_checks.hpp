#pragma once
// The checks every value is put through before it enters the database: a mass that is a finite
// positive number, an inertia a real body can have. Each throws DatabaseError naming `what`.
#include <string>

#include "dynamics/spatial.hpp"

namespace yardsim::yard {

// (mass kg, what) => nothing, or DatabaseError: not finite or not > 0
void checkMass(double mass, const std::string& what);
// (inertia kg m^2 about the centre of mass, what) => nothing, or DatabaseError: not finite, not
// symmetric, not positive definite, or principal moments breaking the triangle inequality
// (each must be at most the sum of the other two, as for any distribution of mass)
void checkInertia(const dynamics::Matrix3& inertia, const std::string& what);

}  // namespace yardsim::yard
