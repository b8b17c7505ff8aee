// The integrators against answers that follow from the physics, not from this code:
// - white furnace: a convex diffuse object of albedo a under a uniform environment L shows a L on
//   every pixel it covers (one bounce, then the ray escapes: no variance at all), L elsewhere. The
//   object is flat-shaded (crease 0): a smooth shading normal tilts from the geometric one, and a
//   sampled direction between the two horizons is dropped (it would leak through the surface), a
//   loss of order sin^2 of the tilt that an exact comparison cannot allow;
// - a concave one (a cup, albedo 1) still shows L, within the Monte Carlo error measured from the
//   pixels themselves;
// - glass of index 1 is invisible;
// - Whitted's diffuse shading of a (polyline) sphere under one point light is a I cos / (pi d^2).
#include "render_support.h"

#include "scene/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

namespace revolve {
namespace {

using testing::renderText;
using testing::spherePointsJson;

std::string number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

std::string furnaceScene(const std::string& profile, double albedo, double environment, const std::string& extra = "",
                         const std::string& from = "[0, -5, 1.2]") {
  const std::string a = number(albedo), l = number(environment);
  return R"({"camera": {"from": )" + from + R"(, "to": [0, 0, 0.3], "up": [0, 0, 1], "fov": 40},
            "profiles": {"shape": {"points": )" +
         profile + R"(, "crease": 0},
                         "glass_block": {"points": [[0, -1.5], [0.8, -1.5], [0.8, 2], [0, 2]]}},
            "materials": {"m": {"type": "diffuse", "color": [)" +
         a + "," + a + "," + a + R"(]},
                          "clear": {"type": "glass", "ior": 1}},
            "objects": [{"profile": "shape", "material": "m"})" +
         extra + R"(],
            "environment": {"color": [)" +
         l + "," + l + "," + l + "]}}";
}

render::RenderSettings smallSettings(int spp, render::IntegratorKind kind = render::IntegratorKind::path,
                                     int depth = 8) {
  render::RenderSettings settings;
  settings.width = 48;
  settings.height = 36;
  settings.spp = spp;
  settings.integrator.kind = kind;
  settings.integrator.depth = depth;
  return settings;
}

TEST(IntegratorClosedFormsTest, ConvexDiffuseObjectUnderUniformSkyShowsAlbedoTimesL) {
  const double environment = 0.7;
  for (const double albedo : {1.0, 0.6}) {
    const testing::RenderRun run =
        renderText(furnaceScene(spherePointsJson(1.0, 48), albedo, environment), smallSettings(4));
    int object = 0;
    for (const float value : run.result.image.pixels) {
      // Pixels on the sphere's silhouette mix samples on and off it: a L <= value <= L.
      EXPECT_GE(value, albedo * environment * (1 - 1e-6));
      EXPECT_LE(value, environment * (1 + 1e-6));
      if (std::abs(value - albedo * environment) <= 1e-6 * environment) ++object;
    }
    if (albedo == 1.0) continue;
    EXPECT_GT(object, 300) << "the sphere covers a good part of the image";
  }
}

TEST(IntegratorClosedFormsTest, WhiteFurnaceWithAConcaveCupStaysWithinMonteCarloError) {
  // A thick-walled cup (outside up, inside down): paths bounce inside it many times before they
  // escape, and Russian roulette ends some; each pixel's expectation is still L.
  const std::string cup = "[[0, 0], [1, 0], [1, 1.2], [0.85, 1.2], [0.85, 0.15], [0, 0.15]]";
  const double environment = 0.5;
  render::RenderSettings settings = smallSettings(1);
  settings.integrator.depth = 64;
  const testing::RenderRun run = renderText(furnaceScene(cup, 1.0, environment, "", "[0, -3, 4]"), settings);
  double sum = 0, sumSquares = 0;
  const auto& pixels = run.result.image.pixels;
  for (const float value : pixels) sum += value, sumSquares += double(value) * value;
  const double n = double(pixels.size()) / 3;  // the three channels are the same path
  const double mean = sum / pixels.size();
  const double variance = std::max(0.0, sumSquares / pixels.size() - mean * mean);
  const double standardError = std::sqrt(variance / n);
  EXPECT_GT(variance, 0) << "the cup's paths should vary (roulette), or the test sees nothing";
  // Truncation at 64 hits loses (0.95)^61 of the surviving weight at most: far below the noise.
  EXPECT_NEAR(mean, environment, 4 * standardError + 1e-6) << "standard error " << standardError;
}

TEST(IntegratorClosedFormsTest, GlassOfIndexOneIsInvisible) {
  const double albedo = 0.5, environment = 0.8;
  const std::string glassInFront = R"(, {"profile": "glass_block", "material": "clear", "translate": [0.3, -2.2, 0]})";
  // No Russian roulette: it would weigh the paths through the glass (two more hits) differently.
  render::RenderSettings settings = smallSettings(1);
  settings.integrator.rouletteAfter = 100;
  const testing::RenderRun with =
      renderText(furnaceScene(spherePointsJson(1.0, 48), albedo, environment, glassInFront), settings);
  const testing::RenderRun without = renderText(furnaceScene(spherePointsJson(1.0, 48), albedo, environment), settings);
  // The rays through the glass go straight on (Fresnel is exactly 0, the direction unchanged), but
  // start again from each crossing's offset origin: a ray through a pixel centre within an offset
  // (a few float ulps) of the sphere's silhouette may flip. Allow 1% of pixels to differ.
  int differing = 0;
  for (std::size_t i = 0; i < with.result.image.pixels.size(); ++i) {
    if (std::abs(with.result.image.pixels[i] - without.result.image.pixels[i]) > 1e-6f) ++differing;
  }
  EXPECT_LE(differing, int(with.result.image.pixels.size() / 100));
  EXPECT_GT(with.result.rays.bounce, 500u) << "the glass must actually be in the way";
}

// The exact sphere |p| = R: nearest t > 0 of o + t d, or nothing.
std::optional<double> sphereHit(const Ray& ray, double radius) {
  const double ox = ray.origin.x, oy = ray.origin.y, oz = ray.origin.z;
  const double dx = ray.direction.x, dy = ray.direction.y, dz = ray.direction.z;
  const double a = dx * dx + dy * dy + dz * dz, b = ox * dx + oy * dy + oz * dz,
               c = ox * ox + oy * oy + oz * oz - radius * radius;
  const double disc = b * b - a * c;
  if (disc < 0) return std::nullopt;
  return (-b - std::sqrt(disc)) / a;
}

TEST(IntegratorClosedFormsTest, WhittedMatchesLambertUnderOnePointLight) {
  const double radius = 1.0, albedo = 0.8, intensity = 10.0;
  const double light[3] = {3, -4, 5};
  const std::string scene =
      std::string(R"({"camera": {"from": [0, -6, 0.5], "to": [0, 0, 0], "up": [0, 0, 1], "fov": 25},
        "profiles": {"ball": {"points": )") +
      spherePointsJson(radius, 800) + R"(}},
        "materials": {"m": {"type": "diffuse", "color": [0.8, 0.8, 0.8]}},
        "objects": [{"profile": "ball", "material": "m"}],
        "lights": [{"type": "point", "position": [3, -4, 5], "intensity": [10, 10, 10]}]})";
  render::RenderSettings settings = smallSettings(1, render::IntegratorKind::whitted, 1);
  settings.width = settings.height = 40;
  const testing::RenderRun run = renderText(scene, settings);
  const scene::Camera camera(run.description.camera, settings.width, settings.height);
  int checked = 0;
  for (int y = 0; y < settings.height; ++y) {
    for (int x = 0; x < settings.width; ++x) {
      const Ray ray = camera.ray(x + 0.5f, y + 0.5f);  // the renderer's ray at spp 1
      const render::Color value = run.result.image.at(x, y);
      const std::optional<double> t = sphereHit(ray, radius);
      if (!t) continue;
      const double p[3] = {ray.origin.x + *t * ray.direction.x, ray.origin.y + *t * ray.direction.y,
                           ray.origin.z + *t * ray.direction.z};
      const double n[3] = {p[0] / radius, p[1] / radius, p[2] / radius};
      const double l[3] = {light[0] - p[0], light[1] - p[1], light[2] - p[2]};
      const double d2 = l[0] * l[0] + l[1] * l[1] + l[2] * l[2];
      const double cosLight = (n[0] * l[0] + n[1] * l[1] + n[2] * l[2]) / std::sqrt(d2);
      const double view = -(n[0] * ray.direction.x + n[1] * ray.direction.y + n[2] * ray.direction.z);
      // Away from the silhouette and the terminator, where the polyline (inscribed, 800 chords:
      // within 7.7e-6 R of the sphere) and the sphere could differ in hit or in shadow.
      if (view < 0.1 || std::abs(cosLight) < 0.02) continue;
      const double expected = cosLight > 0 ? albedo / 3.14159265358979323846 * intensity * cosLight / d2 : 0.0;
      // The hit lies up to 7.7e-6 deeper along the ray than the sphere's (over a view cosine >= 0.1:
      // 7.7e-5), moving d and the shading normal's angle by as much: 2e-4 relative covers it.
      EXPECT_NEAR(value.r, expected, 2e-4 * expected + 1e-7) << "pixel " << x << ", " << y;
      EXPECT_EQ(value.r, value.g);
      ++checked;
    }
  }
  EXPECT_GT(checked, 300);
}

// A hollow tube of index-1 glass (no reflection, rays straight through) under a uniform sky: the
// ray through the image's centre crosses four walls, so Whitted shows the sky from five levels on
// (the default, 8, included) and black below.
TEST(IntegratorClosedFormsTest, WhittedSeesThroughHollowGlassFromFiveLevels) {
  const std::string scene = R"({"camera": {"from": [0, -6, 0], "to": [0, 0, 0], "up": [0, 0, 1], "fov": 20},
      "profiles": {"tube": {"points": [[0.9, -1], [1, -1], [1, 1], [0.9, 1], [0.9, -1]]}},
      "materials": {"clear": {"type": "glass", "ior": 1}},
      "objects": [{"profile": "tube", "material": "clear"}],
      "environment": {"color": [0.7, 0.7, 0.7]}})";
  for (const int depth : {0, 4, 5}) {
    render::RenderSettings settings = smallSettings(1, render::IntegratorKind::whitted);
    settings.width = 9, settings.height = 7;  // the centre pixel's ray is the camera's axis
    if (depth > 0) settings.integrator.depth = depth;
    const testing::RenderRun run = renderText(scene, settings);
    EXPECT_EQ(run.result.image.at(4, 3).g, depth == 4 ? 0.0f : 0.7f)
        << "depth " << (depth > 0 ? depth : settings.integrator.depth);
  }
}

// Filtered shadows: a point light above a glass disc over a diffuse floor. Straight down, the
// shadow ray crosses the disc's two faces at normal incidence, each passing 1 - F = 1 - ((n - 1) /
// (n + 1))^2 of the light times the tint; the floor under it shows a I / (pi d^2) times that.
// Without filtering, the disc's shadow is black.
TEST(IntegratorClosedFormsTest, WhittedFilteredShadowsPassFresnelTransmissionAndTint) {
  const double albedo = 0.5, intensity = 40, height = 10, ior = 1.5, tint = 0.8;
  const std::string scene = R"({"camera": {"from": [6, 0, 1], "to": [0, 0, 0], "up": [0, 0, 1], "fov": 10},
      "profiles": {"disc": {"points": [[0, 4], [2, 4], [2, 5], [0, 5]]}},
      "materials": {"floor": {"type": "diffuse", "color": [0.5, 0.5, 0.5]},
                    "glass": {"type": "glass", "ior": 1.5, "tint": [0.8, 0.8, 0.8]}},
      "objects": [{"profile": "disc", "material": "glass"}],
      "quads": [{"corners": [[-50, -50, 0], [50, -50, 0], [50, 50, 0], [-50, 50, 0]], "material": "floor"}],
      "lights": [{"type": "point", "position": [0, 0, 10], "intensity": [40, 40, 40]}]})";
  const double f = (ior - 1) / (ior + 1) * (ior - 1) / (ior + 1);
  const double unshadowed = albedo / 3.14159265358979323846 * intensity / (height * height);
  for (const bool filtered : {false, true}) {
    render::RenderSettings settings = smallSettings(1, render::IntegratorKind::whitted);
    settings.width = 9, settings.height = 7;
    settings.integrator.filteredShadows = filtered;
    const testing::RenderRun run = renderText(scene, settings);
    const double expected = filtered ? unshadowed * (1 - f) * tint * (1 - f) * tint : 0.0;
    // The centre ray meets the floor within a float rounding of the origin: cos and d are 1 and 10.
    EXPECT_NEAR(run.result.image.at(4, 3).g, expected, 1e-5 * unshadowed) << (filtered ? "filtered" : "opaque");
  }
}

}  // namespace
}  // namespace revolve
