// A beam's footprint. A real laser beam is a narrow cone, not a ray: where it straddles an edge (a
// pole in front of a wall) part of its light comes back from each surface, and the sensor sees two
// echoes. The cone of full angle `divergence` about the beam's axis is sampled by `subrays` rays
// laid out on Vogel's (1979) sunflower spiral, which gives every sub-ray an equal share of the
// cone's cross-section and puts no two on one line through the axis:
//
//   sub-ray k of n (k = 0 .. n-1) leaves the axis by rho_k = (divergence / 2) sqrt((k + 1/2) / n),
//   turned phi_k = k * pi (3 - sqrt 5) (the golden angle) about the axis, measured from the
//   direction of increasing azimuth toward increasing elevation;
//
// with n = 1 the one sub-ray is the axis. Each sub-ray carries 1/n of the beam's light.
#pragma once

#include "geometry/vec3d.h"

#include <cmath>
#include <numbers>
#include <vector>

namespace revolve::robot {

using app::Vec3d;

// A sub-ray's direction in a beam's own axes: along * axis + across * (increasing azimuth) + up *
// (increasing elevation); unit length.
struct SubrayOffset {
  double along = 1, across = 0, up = 0;
};

inline std::vector<SubrayOffset> footprintOffsets(double divergence, int subrays) {
  if (subrays == 1) return {SubrayOffset{}};
  const double golden = std::numbers::pi * (3 - std::sqrt(5.0));
  std::vector<SubrayOffset> offsets(static_cast<std::size_t>(subrays));
  for (int k = 0; k < subrays; ++k) {
    const double rho = divergence / 2 * std::sqrt((k + 0.5) / subrays), phi = k * golden;
    offsets[std::size_t(k)] = {std::cos(rho), std::sin(rho) * std::cos(phi), std::sin(rho) * std::sin(phi)};
  }
  return offsets;
}

// A beam's axes in the sensor's frame, from its azimuth and elevation (their sines and cosines):
// the axis, the direction of increasing azimuth and that of increasing elevation, orthonormal.
struct BeamAxes {
  Vec3d axis, across, up;

  static BeamAxes at(double cosAzimuth, double sinAzimuth, double cosElevation, double sinElevation) {
    return {{cosElevation * cosAzimuth, cosElevation * sinAzimuth, sinElevation},
            {-sinAzimuth, cosAzimuth, 0},
            {-sinElevation * cosAzimuth, -sinElevation * sinAzimuth, cosElevation}};
  }
  Vec3d direction(const SubrayOffset& o) const {
    return {o.along * axis[0] + o.across * across[0] + o.up * up[0],
            o.along * axis[1] + o.across * across[1] + o.up * up[1],
            o.along * axis[2] + o.across * across[2] + o.up * up[2]};
  }
};

}  // namespace revolve::robot
