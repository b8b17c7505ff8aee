// Inside or outside the solid a closed profile bounds, decided in the meridian plane from the
// profile itself (its polyline, or its Bezier pieces for a spline traced exactly), not from rays:
// what compute_signed_distance and compute_occupancy take their sign from.
#pragma once

#include <revolve/revolve.h>

namespace revolve::python {

// Whether the point at distance `rho` >= 0 from the axis and height `z` lies inside the solid of a
// closed shape (Shape::profile().closed(), or its spline's closed()). The crossing number of the
// half-line {(r, z) : r > rho} with the curve closed along the axis (whose own points, r = 0,
// never cross it): each piece is split where z turns, each part monotone in z counted once when
// its ends lie on opposite sides of the line by the half-open rule (z > height or not, so that
// neighbours sharing an end agree), and its crossing found by bisection in double. Points within
// rounding of the curve may land on either side; their distance is zero to that rounding anyway.
bool insideSolid(const Shape& shape, double rho, double z) noexcept;

}  // namespace revolve::python
