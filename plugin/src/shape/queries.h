// Queries shared by the public functions and the Embree glue.
#pragma once

#include "shape/shape_impl.h"

namespace revolve::detail {

// The closest surface point to p (see revolve::closestPoint). A non-finite p gives distance NaN.
SurfacePoint closestSurfacePoint(const detail::ShapeImpl& shape, Vec3 p) noexcept;

}  // namespace revolve::detail
