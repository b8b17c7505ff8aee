#include "embree/placed_callbacks.h"

#include "util/rounding.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace revolve::detail {
namespace {

// The world rays of a packet's valid lanes, kept to be put back.
struct WorldLanes {
  float origin[3][16], direction[3][16];
};

// Each valid lane's ray in object space: o' = L^-1 (o - T), d' = L^-1 d, in double from the float
// ray, each component rounded once to float. tnear and tfar are unchanged (an affine map keeps the
// ray's parameter), and so is every other field.
void mapLanes(const PlacementMaps& maps, RTCRayN* rays, unsigned N, const int* valid, WorldLanes& world) noexcept {
  for (unsigned i = 0; i < N; ++i) {
    if (valid[i] != -1) continue;
    float* origin[3] = {&RTCRayN_org_x(rays, N, i), &RTCRayN_org_y(rays, N, i), &RTCRayN_org_z(rays, N, i)};
    float* direction[3] = {&RTCRayN_dir_x(rays, N, i), &RTCRayN_dir_y(rays, N, i), &RTCRayN_dir_z(rays, N, i)};
    double o[3], d[3];
    for (int k = 0; k < 3; ++k) {
      world.origin[k][i] = *origin[k];
      world.direction[k][i] = *direction[k];
      o[k] = double(*origin[k]) - maps.translate[k];
      d[k] = *direction[k];
    }
    for (int r = 0; r < 3; ++r) {
      const double* m = maps.inverse[r];
      *origin[r] = float(m[0] * o[0] + m[1] * o[1] + m[2] * o[2]);
      *direction[r] = float(m[0] * d[0] + m[1] * d[1] + m[2] * d[2]);
    }
  }
}

void restoreLanes(const WorldLanes& world, RTCRayN* rays, unsigned N, const int* valid) noexcept {
  for (unsigned i = 0; i < N; ++i) {
    if (valid[i] != -1) continue;
    RTCRayN_org_x(rays, N, i) = world.origin[0][i];
    RTCRayN_org_y(rays, N, i) = world.origin[1][i];
    RTCRayN_org_z(rays, N, i) = world.origin[2][i];
    RTCRayN_dir_x(rays, N, i) = world.direction[0][i];
    RTCRayN_dir_y(rays, N, i) = world.direction[1][i];
    RTCRayN_dir_z(rays, N, i) = world.direction[2][i];
  }
}

}  // namespace

PlacementMaps placementMaps(const Placement& placement) {
  PlacementMaps maps{};
  const auto& a = placement.linear;
  for (int r = 0; r < 3; ++r) {
    maps.translate[r] = placement.translate[r];
    if (!std::isfinite(placement.translate[r]))
      throw std::invalid_argument("placement: translate[" + std::to_string(r) + "] is not finite");
    for (int c = 0; c < 3; ++c) {
      maps.linear[r][c] = a[r][c];
      if (!std::isfinite(a[r][c])) {
        throw std::invalid_argument("placement: linear[" + std::to_string(r) + "][" + std::to_string(c) +
                                    "] is not finite");
      }
    }
  }
  // The inverse by cofactors.
  const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                     a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                     a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      // inverse[r][c] = cofactor of a[c][r] / det
      const int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
      maps.inverse[r][c] = (a[r1][c1] * a[r2][c2] - a[r1][c2] * a[r2][c1]) / det;
      if (!std::isfinite(maps.inverse[r][c]))
        throw std::invalid_argument("placement: the linear part is singular (its inverse is not finite)");
    }
  }
  return maps;
}

Vec3 toObjectSpace(const PlacementMaps& maps, Vec3 world) noexcept {
  const double p[3] = {double(world.x) - maps.translate[0], double(world.y) - maps.translate[1],
                       double(world.z) - maps.translate[2]};
  const auto row = [&](int r) {
    return float(maps.inverse[r][0] * p[0] + maps.inverse[r][1] * p[1] + maps.inverse[r][2] * p[2]);
  };
  return {row(0), row(1), row(2)};
}

Vec3 toWorldSpace(const PlacementMaps& maps, Vec3 object) noexcept {
  const auto row = [&](int r) {
    return float(maps.linear[r][0] * object.x + maps.linear[r][1] * object.y + maps.linear[r][2] * object.z +
                 maps.translate[r]);
  };
  return {row(0), row(1), row(2)};
}

void placedBoundsCallback(const RTCBoundsFunctionArguments* args) {
  const auto& payload = *static_cast<const GeometryPayload*>(args->geometryUserPtr);
  const PlacementMaps& maps = *payload.placement;
  const Bounds b = payload.shape->bounds;
  // The box's eight corners mapped in double: each coordinate, three products and three additions,
  // is within gamma(4) (double) of its magnitude sum; x - error and x + error round once more, by
  // at most u (|x| + error), so gamma(5) of the magnitude sum widens the box enough before it is
  // rounded outwards to float: the float box holds the exactly placed one.
  constexpr double kGamma5 = 5 * kUnitRoundoff / (1 - 5 * kUnitRoundoff);
  double lower[3], upper[3];
  for (int r = 0; r < 3; ++r) {
    lower[r] = std::numeric_limits<double>::infinity();
    upper[r] = -std::numeric_limits<double>::infinity();
  }
  for (int corner = 0; corner < 8; ++corner) {
    const double p[3] = {(corner & 1) ? b.upper.x : b.lower.x, (corner & 2) ? b.upper.y : b.lower.y,
                         (corner & 4) ? b.upper.z : b.lower.z};
    for (int r = 0; r < 3; ++r) {
      const double* m = maps.linear[r];
      const double x = m[0] * p[0] + m[1] * p[1] + m[2] * p[2] + maps.translate[r];
      const double error = kGamma5 * (std::abs(m[0] * p[0]) + std::abs(m[1] * p[1]) + std::abs(m[2] * p[2]) +
                                      std::abs(maps.translate[r]));
      lower[r] = std::min(lower[r], x - error);
      upper[r] = std::max(upper[r], x + error);
    }
  }
  RTCBounds& out = *args->bounds_o;
  out.lower_x = floatBelow(lower[0]);
  out.lower_y = floatBelow(lower[1]);
  out.lower_z = floatBelow(lower[2]);
  out.upper_x = floatAbove(upper[0]);
  out.upper_y = floatAbove(upper[1]);
  out.upper_z = floatAbove(upper[2]);
}

void placedIntersectCallback(const RTCIntersectFunctionNArguments* args) {
  const auto& payload = *static_cast<const GeometryPayload*>(args->geometryUserPtr);
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
  WorldLanes world;
  mapLanes(*payload.placement, rays, args->N, args->valid, world);
  payload.objectIntersect(args);
  restoreLanes(world, rays, args->N, args->valid);
}

void placedOccludedCallback(const RTCOccludedFunctionNArguments* args) {
  const auto& payload = *static_cast<const GeometryPayload*>(args->geometryUserPtr);
  WorldLanes world;
  mapLanes(*payload.placement, args->ray, args->N, args->valid, world);
  payload.objectOccluded(args);
  // An occluded lane's tfar is -inf now, and its origin and direction are put back all the same.
  restoreLanes(world, args->ray, args->N, args->valid);
}

}  // namespace revolve::detail
