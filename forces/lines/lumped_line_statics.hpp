#pragma once
// The static equilibrium of a lumped-mass line (lumped_line.hpp) with both ends held: the inner
// node positions where the conservative node forces (the segments' EA e, the net weight, the bed
// springs, the bending: LumpedLine::conservativeForces) vanish, by Newton's method on the
// 3 (N - 1) positions with the analytic stiffness of the segments (EA/l along a taut segment, T/|d|
// across it), of the bending and of the bed, from a guess (the catenary's points), each step
// halved until it reduces the residual or the line's potential energy (the forces are its
// negative gradient: an Armijo condition); the stiffness is a band matrix, factorised in
// O(nodes) (dynamics/integrators/bordered_band_lu.hpp; a dense LU was O(nodes^3)). A line placed on
// the continuous catenary is not at rest as a chain of straight segments (its chords are shorter
// than its arcs by l dtheta^2 / 24, more than the elastic stretch of a stiff chain), so lumped
// lines start from this equilibrium. World frame, SI units.
#include <Eigen/Core>

#include "forces/lines/lumped_line.hpp"

namespace yardsim::forces {

// (line, r: 3 x nodes, the ends held and the inner nodes a guess) => r at rest; true when the
// largest residual node force is below 1e-9 of the line's weight |w| L (at most 500 steps)
bool lumpedLineStatics(const LumpedLine& line, Eigen::Matrix3Xd& r);

}  // namespace yardsim::forces
