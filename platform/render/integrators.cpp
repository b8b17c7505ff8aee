#include "render/integrators.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace revolve::render {

using namespace app;

namespace {

struct ShadingFrame {
  Vec3 wo, shading, geometric;
  bool outside;  // wo on the side the surface's own normal points to
};

// Both normals turned to the viewer's side (surfaces are two-sided), and a shading normal that
// faces away from the viewer (possible near silhouettes) replaced by the geometric one. Glass keeps
// its orientation: it needs to know whether the ray enters or leaves.
ShadingFrame shadingFrame(const scene::WorldHit& hit, Vec3 rayDirection, bool glass) {
  ShadingFrame f;
  f.wo = -normalize(rayDirection);
  f.geometric = hit.geometricNormal;
  f.shading = hit.shadingNormal;
  f.outside = dot(f.wo, f.geometric) >= 0;
  if (glass) return f;
  if (!f.outside) f.geometric = -f.geometric, f.shading = -f.shading;
  if (dot(f.shading, f.wo) <= 0) f.shading = f.geometric;
  return f;
}

// Veach's power heuristic (beta = 2) for the strategy of density `a` against one of density `b`.
float powerHeuristic(float a, float b) {
  const float a2 = a * a, b2 = b * b;
  return a2 > 0 ? a2 / (a2 + b2) : 0;
}

}  // namespace

Color Integrator::radiance(const Ray& cameraRay, RandomStream& random, RayCounts& counts) const {
  return radiance(cameraRay, nearestHit(cameraRay, counts), random, counts);
}

Color Integrator::radiance(const Ray& cameraRay, const std::optional<scene::WorldHit>& cameraHit, RandomStream& random,
                           RayCounts& counts) const {
  ++counts.camera;
  if (settings_.kind == IntegratorKind::whitted) return whitted(cameraRay, cameraHit, 1, random, counts);
  return path(cameraRay, cameraHit, random, counts);
}

std::optional<scene::WorldHit> Integrator::nearestHit(const Ray& ray, RayCounts& counts) const {
  const PhaseScope phase(counts.clock, Phase::intersection);
  return scene_.intersect(ray);
}

Color Integrator::direct(const scene::WorldHit& hit, const Material& material, Vec3 wo, Vec3 shading, Vec3 geometric,
                         bool shadowRays, bool mis, RandomStream& random, RayCounts& counts) const {
  Color sum;
  for (std::size_t i = 0; i < lights_.count(); ++i) {
    const LightSample light = [&] {
      const PhaseScope phase(counts.clock, Phase::sampling);
      return lights_.sample(i, hit.point, random);
    }();
    Color f = material.evaluate(wo, light.wi, shading, geometric);
    if (f.black() || light.irradiance.black()) continue;
    if (mis && light.pdf > 0) f = powerHeuristic(light.pdf, material.pdf(wo, light.wi, shading)) * f;
    if (shadowRays) f = f * visibility(hit, light, counts);
    sum += f * light.irradiance;
  }
  return sum;
}

Color Integrator::visibility(const scene::WorldHit& from, const LightSample& light, RayCounts& counts) const {
  const PhaseScope phase(counts.clock, Phase::shadows);
  Ray shadow;
  shadow.origin = scene_.spawn(from, light.wi);
  // To a point light: the segment up to it (t in units of the unnormalised direction); to the sun: the whole ray.
  shadow.direction = light.atInfinity ? light.wi : light.position - shadow.origin;
  shadow.tfar = light.atInfinity ? std::numeric_limits<float>::infinity() : 1.0f;
  ++counts.shadow;
  if (!settings_.filteredShadows) return scene_.occluded(shadow) ? Color{} : Color{1, 1, 1};
  // Filtered: follow the straight line through every glass surface it crosses. A bound on the
  // crossings keeps the loop finite whatever the scene; 64 is 32 glass walls in a row.
  Color filter{1, 1, 1};
  for (int crossing = 0; crossing < 64; ++crossing) {
    const std::optional<scene::WorldHit> hit = scene_.intersect(shadow);
    if (!hit) return filter;
    const Material& material = materials_[hit->material];
    filter = filter * material.straightTransmittance(std::abs(dot(light.wi, hit->shadingNormal)));
    if (filter.black()) return {};
    shadow.origin = scene_.spawn(*hit, light.wi);
    if (!light.atInfinity) shadow.direction = light.position - shadow.origin;
    ++counts.shadow;
  }
  return {};
}

Color Integrator::path(Ray ray, std::optional<scene::WorldHit> hit, RandomStream& random, RayCounts& counts) const {
  Color radiance, throughput{1, 1, 1};
  // The density of the last scatter's direction (0 after a delta lobe or for the camera ray), and
  // whether the path has scattered off a diffuse or glossy lobe yet (regularisation starts then).
  float scatterPdf = 0;
  bool indirect = false;
  for (int hits = 1;; ++hits) {
    if (hits > 1) hit = nearestHit(ray, counts);
    if (!hit) {
      const Vec3 d = normalize(ray.direction);
      Color escaped = lights_.environment(d);
      // A sun reached by a BSDF sample: its share of the two strategies (the light-sampled share
      // was added at the vertex that sampled this ray).
      for (std::size_t i = 0; scatterPdf > 0 && i < lights_.count(); ++i) {
        const LightSeen light = lights_.seen(i, d);
        if (light.pdf > 0) escaped += powerHeuristic(scatterPdf, light.pdf) * light.radiance;
      }
      radiance += throughput * escaped;
      break;
    }
    const Material& stored = materials_[hit->material];
    const Material material = settings_.regularize && indirect ? stored.regularized() : stored;
    const ShadingFrame f = shadingFrame(*hit, ray.direction, material.type() == io::MaterialType::glass);
    if (material.hasSmoothLobe()) {
      radiance += throughput * direct(*hit, material, f.wo, f.shading, f.geometric, true, true, random, counts);
    }
    if (hits >= settings_.depth) break;
    const std::optional<ScatterSample> scatter = [&] {
      const PhaseScope phase(counts.clock, Phase::sampling);
      return material.sample(f.wo, f.shading, f.geometric, f.outside, random);
    }();
    if (!scatter) break;
    scatterPdf = scatter->specular ? 0 : scatter->pdf;
    indirect = indirect || !scatter->specular;
    throughput = throughput * scatter->weight;
    if (hits >= settings_.rouletteAfter) {
      // Continue with probability q, weighting survivors by 1 / q: unbiased, and a dim path ends early.
      const float q = std::min(throughput.max(), 0.95f);
      const float u = [&] {
        const PhaseScope phase(counts.clock, Phase::sampling);
        return random.next();
      }();
      if (!(u < q)) break;
      throughput = (1 / q) * throughput;
    }
    ray = Ray{scene_.spawn(*hit, scatter->wi), scatter->wi};
    ++counts.bounce;
  }
  return radiance;
}

Color Integrator::whitted(const Ray& ray, const std::optional<scene::WorldHit>& hit, int level, RandomStream& random,
                          RayCounts& counts) const {
  if (!hit) return lights_.environment(normalize(ray.direction));
  const Material& material = materials_[hit->material];
  const bool glass = material.type() == io::MaterialType::glass;
  const ShadingFrame f = shadingFrame(*hit, ray.direction, glass);
  Color radiance;
  if (material.hasSmoothLobe()) {
    radiance += direct(*hit, material, f.wo, f.shading, f.geometric, settings_.shadows, false, random, counts);
    // The classic ambient term: diffuse surfaces take the environment seen along their normal.
    if (material.type() == io::MaterialType::diffuse) radiance += material.color() * lights_.environment(f.shading);
  }
  if (level >= settings_.depth) return radiance;
  const auto trace = [&](Vec3 direction) {
    ++counts.bounce;
    const Ray next{scene_.spawn(*hit, direction), direction};
    return whitted(next, nearestHit(next, counts), level + 1, random, counts);
  };
  if (glass) {
    const Material::Split split = material.glassSplit(f.wo, f.shading, f.outside);
    const Vec3 n = dot(f.wo, f.shading) >= 0 ? f.shading : -f.shading;
    const Vec3 reflected = reflect(f.wo, n);
    if (split.reflectance > 0) radiance += split.reflectance * trace(reflected);
    if (split.refracted) radiance += (1 - split.reflectance) * (material.tint() * trace(*split.refracted));
  } else if (material.type() != io::MaterialType::diffuse) {
    const Vec3 reflected = reflect(f.wo, f.shading);
    if (dot(reflected, f.geometric) > 0) radiance += material.specularReflectance(f.wo, f.shading) * trace(reflected);
  }
  return radiance;
}

}  // namespace revolve::render
