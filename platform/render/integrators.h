// Radiance along a camera ray: unidirectional path tracing, or the Whitted ray tracer of Baciu, Jia & Lam (2001).
#pragma once

#include "render/color.h"
#include "render/lights.h"
#include "render/materials.h"
#include "render/phase_clock.h"
#include "render/random_stream.h"
#include "scene/embree_scene.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace revolve::render {

enum class IntegratorKind { path, whitted };

// The rays a tile traced and, when --stats asks (clock not null), where its time went.
struct RayCounts {
  std::uint64_t camera = 0, bounce = 0, shadow = 0;
  PhaseClock* clock = nullptr;  // the tile's own; += leaves it alone
  RayCounts& operator+=(const RayCounts& o) {
    camera += o.camera, bounce += o.bounce, shadow += o.shadow;
    return *this;
  }
};

struct IntegratorSettings {
  IntegratorKind kind = IntegratorKind::path;
  // path: most surface hits a path has; whitted: ray levels (1 = ray casting). Whitted's 8 lets
  // hollow glass through (five levels: four crossings of its walls and the ray beyond) with three
  // to spare for glass seen in glass or in a mirror.
  int depth = 8;
  bool shadows = true;    // whitted: shadow rays to the lights (off: Baciu, Jia & Lam's Example 1)
  int rouletteAfter = 3;  // path: Russian roulette from this many hits on
  // path: regularise glossy metal after the first diffuse or glossy bounce (Material::regularized).
  // Biased (caustics and glossy inter-reflections come out blurred); off for reference renders.
  bool regularize = true;
  // whitted: shadow rays pass straight through glass, dimmed by each crossing's Fresnel
  // transmission and tint (POV-Ray's filtered shadows), instead of being blocked by it.
  bool filteredShadows = false;
};

class Integrator {
 public:
  Integrator(const scene::EmbreeScene& scene, const std::vector<Material>& materials, const Lights& lights,
             const IntegratorSettings& settings)
      : scene_(scene), materials_(materials), lights_(lights), settings_(settings) {}

  // Never allocates, throws or locks.
  Color radiance(const Ray& cameraRay, RandomStream& random, RayCounts& counts) const;
  // The same, given the camera ray's nearest hit (scene.intersect(cameraRay), or a lane of a packet
  // of camera rays): the same random numbers drawn, the same result bit for bit.
  Color radiance(const Ray& cameraRay, const std::optional<scene::WorldHit>& cameraHit, RandomStream& random,
                 RayCounts& counts) const;

 private:
  // Each from `ray` and its nearest hit `hit`.
  Color path(Ray ray, std::optional<scene::WorldHit> hit, RandomStream& random, RayCounts& counts) const;
  Color whitted(const Ray& ray, const std::optional<scene::WorldHit>& hit, int level, RandomStream& random,
                RayCounts& counts) const;
  std::optional<scene::WorldHit> nearestHit(const Ray& ray, RayCounts& counts) const;
  // Light arriving from every light at a hit, times f cos: next-event estimation. With `mis`, a
  // light that BSDF sampling can also reach (a sun with a cone) is weighted by the power heuristic.
  Color direct(const scene::WorldHit& hit, const Material& material, Vec3 wo, Vec3 shading, Vec3 geometric,
               bool shadowRays, bool mis, RandomStream& random, RayCounts& counts) const;
  // The fraction of a light sample's light that reaches `from`: 0 or 1 by a shadow ray, or with
  // filtered shadows the product of the glass surfaces' filters along the straight line.
  Color visibility(const scene::WorldHit& from, const LightSample& light, RayCounts& counts) const;

  const scene::EmbreeScene& scene_;
  const std::vector<Material>& materials_;
  const Lights& lights_;
  IntegratorSettings settings_;
};

}  // namespace revolve::render
