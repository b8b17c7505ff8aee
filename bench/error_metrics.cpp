#include "error_metrics.h"

#include "ray_batches.h"

#include "embree/embree_rays.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace revolve::bench {
namespace {

double percentile(std::vector<double> values, double fraction) {
  if (values.empty()) return 0.0;
  const std::size_t index = std::min(values.size() - 1, std::size_t(fraction * double(values.size())));
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(index), values.end());
  return values[index];
}

}  // namespace

std::vector<ReferenceHit> referenceHits(const ReferenceTracer& tracer, const std::vector<Ray>& rays) {
  std::vector<ReferenceHit> hits(rays.size());
  tbb::parallel_for(std::size_t{0}, rays.size(), [&](std::size_t i) { hits[i] = tracer.trace(rays[i]); });
  return hits;
}

ErrorSummary measureErrors(RTCScene scene, const std::vector<Ray>& rays, const std::vector<ReferenceHit>& reference,
                           const ReferenceTracer& tracer, double size, bool orientedNormals) {
  struct PerRay {
    bool hit;
    double residual, normalDegrees, sheetOffset;
  };
  std::vector<PerRay> results(rays.size());
  tbb::parallel_for(std::size_t{0}, rays.size(), [&](std::size_t i) {
    embree::RayQuery query;
    RTCRayHit rayHit = app::embreeRayHit(rays[i]);
    query.intersect(scene, rayHit);
    PerRay& result = results[i];
    result.hit = rayHit.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    if (!result.hit) return;
    const Ray& ray = rays[i];
    const double t = rayHit.ray.tfar;
    const double p[3] = {ray.origin.x + t * ray.direction.x, ray.origin.y + t * ray.direction.y,
                         ray.origin.z + t * ray.direction.z};
    const ClosestPoint closest = tracer.closestTo(p);
    result.residual = closest.distance / size;
    if (reference[i].hit) {
      const ReferenceHit& first = reference[i];
      result.sheetOffset =
          std::abs((p[0] - first.point[0]) * first.normal[0] + (p[1] - first.point[1]) * first.normal[1] +
                   (p[2] - first.point[2]) * first.normal[2]) /
          size;
    }
    const double rho = std::hypot(p[0], p[1]);
    const double c = rho > 0.0 ? p[0] / rho : 1.0, s = rho > 0.0 ? p[1] / rho : 0.0;
    const double truth[3] = {closest.normal.r * c, closest.normal.r * s, closest.normal.z};
    double n[3] = {rayHit.hit.Ng_x, rayHit.hit.Ng_y, rayHit.hit.Ng_z};
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& x : n) x /= length;
    const double cross[3] = {n[1] * truth[2] - n[2] * truth[1], n[2] * truth[0] - n[0] * truth[2],
                             n[0] * truth[1] - n[1] * truth[0]};
    const double sine = std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]);
    const double dot = n[0] * truth[0] + n[1] * truth[1] + n[2] * truth[2];
    const double cosine = orientedNormals ? dot : std::abs(dot);
    result.normalDegrees = std::atan2(sine, cosine) * 180.0 / std::numbers::pi;
  });

  ErrorSummary summary;
  summary.rays = rays.size();
  std::vector<double> residuals, normals;
  double sum2 = 0.0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const PerRay& result = results[i];
    if (!reference[i].grazing) {
      ++summary.decided;
      if (result.hit != reference[i].hit) ++summary.disagreements;
      if (result.hit && reference[i].hit) {
        ++summary.bothHit;
        if (result.sheetOffset > ErrorSummary::kOtherSheet) ++summary.otherSheet;
      }
    }
    if (!result.hit) continue;
    ++summary.hits;
    residuals.push_back(result.residual);
    normals.push_back(result.normalDegrees);
    sum2 += result.residual * result.residual;
  }
  if (!residuals.empty()) {
    summary.residualMax = *std::max_element(residuals.begin(), residuals.end());
    summary.residualP99 = percentile(residuals, 0.99);
    summary.residualRms = std::sqrt(sum2 / double(residuals.size()));
    summary.normalMaxDegrees = *std::max_element(normals.begin(), normals.end());
    summary.normalP99Degrees = percentile(normals, 0.99);
  }
  return summary;
}

}  // namespace revolve::bench
