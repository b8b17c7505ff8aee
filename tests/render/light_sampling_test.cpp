// The path tracer's two ways to a sun of finite size, weighed by multiple importance sampling
// (the power heuristic), against answers that do not come from the renderer:
// - a diffuse plane under a sun of half-angle b straight above reflects a E sin^2(b) / Omega
//   (the cosine integrated over the sun's cone, times its radiance E / Omega, times a / pi);
// - a GGX metal plane reflects the integral over the cone of f(wo, wi) cos(theta_i) E / Omega,
//   computed here by quadrature from the textbook microfacet model (Walter et al. 2007; Heitz
//   2014's height-correlated Smith shadowing; Schlick's Fresnel), written out below, not taken
//   from the renderer.
// Counting a sun twice (both strategies at full weight) or never from one of them would miss the
// answers by the other strategy's share, far outside the Monte Carlo error at these sizes.
#include "render_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <ostream>
#include <string>

namespace revolve {
namespace {

constexpr double kPi = std::numbers::pi;

struct V {
  double x, y, z;
};
V operator*(double s, V a) { return {s * a.x, s * a.y, s * a.z}; }
V operator+(V a, V b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
double dot(V a, V b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V unit(V a) { return (1 / std::sqrt(dot(a, a))) * a; }
V cross(V a, V b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
// A direction `degrees` from +z towards +x (y = 0).
V tilted(double degrees) {
  const double t = degrees * kPi / 180;
  return {std::sin(t), 0, std::cos(t)};
}
std::string json(V v) {
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, "[%.17g, %.17g, %.17g]", v.x, v.y, v.z);
  return buffer;
}

// GGX on the plane z = 0 (normal +z), grey Schlick Fresnel f0; f(wo, wi) cos(theta_i).
double ggxTimesCosine(V wo, V wi, double alpha, double f0) {
  if (wo.z <= 0 || wi.z <= 0) return 0;
  const V h = unit(wo + wi);
  const double a2 = alpha * alpha, c2 = h.z * h.z;
  const double d = a2 / (kPi * (c2 * (a2 - 1) + 1) * (c2 * (a2 - 1) + 1));
  const auto lambda = [&](V w) { return 0.5 * (std::sqrt(1 + a2 * (1 - w.z * w.z) / (w.z * w.z)) - 1); };
  const double g2 = 1 / (1 + lambda(wo) + lambda(wi));
  const double fresnel = f0 + (1 - f0) * std::pow(1 - dot(wo, h), 5);
  return d * g2 * fresnel / (4 * wo.z);
}

// The integral over the sun's cone (axis `towardsSun`, half-angle `half`) of f cos E / Omega, by
// the midpoint rule in (polar, azimuth) about the axis.
double sunReflection(V wo, V towardsSun, double halfDegrees, double irradiance, double alpha, double f0) {
  const double half = halfDegrees * kPi / 180, solidAngle = 2 * kPi * (1 - std::cos(half));
  const V s = unit(cross(towardsSun, std::abs(towardsSun.z) < 0.9 ? V{0, 0, 1} : V{1, 0, 0})), t = cross(towardsSun, s);
  const int n = 600;
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double theta = (i + 0.5) * half / n;
    for (int j = 0; j < n; ++j) {
      const double phi = (j + 0.5) * 2 * kPi / n;
      const V wi =
          std::cos(theta) * towardsSun + (std::sin(theta) * std::cos(phi)) * s + (std::sin(theta) * std::sin(phi)) * t;
      sum += ggxTimesCosine(wo, wi, alpha, f0) * std::sin(theta);
    }
  }
  return sum * (half / n) * (2 * kPi / n) * irradiance / solidAngle;
}

struct Estimate {
  double mean, standardError;
};

// The path tracer's radiance towards `wo` from the point (0, 0, 0) of a large plane of `material`
// under one sun and nothing else, averaged over `samples` samples.
Estimate planeUnderSun(const std::string& material, V towardsSun, double angleDegrees, double irradiance, V wo,
                       int samples) {
  const std::string text = R"({"camera": {"from": [0, -5, 5], "to": [0, 0, 0], "up": [0, 0, 1], "fov": 30},
      "profiles": {}, "materials": {"m": )" +
                           material + R"(},
      "objects": [],
      "quads": [{"corners": [[-1000, -1000, 0], [1000, -1000, 0], [1000, 1000, 0], [-1000, 1000, 0]], "material": "m"}],
      "lights": [{"type": "sun", "direction": )" +
                           json(-1 * towardsSun) + R"(, "irradiance": [)" + std::to_string(irradiance) + "," +
                           std::to_string(irradiance) + "," + std::to_string(irradiance) + R"(], "angle": )" +
                           std::to_string(angleDegrees) + "}]}";
  const io::SceneDescription description = io::parseScene(text, "test.json", ".");
  const scene::EmbreeScene built(description, {});
  std::vector<render::Material> materials;
  for (const io::SceneMaterial& m : description.materials) materials.emplace_back(m);
  const render::Lights lights(description.lights, description.environment);
  const render::Integrator integrator(built, materials, lights, render::IntegratorSettings{});
  const V origin = 2.0 * wo;
  Ray ray;
  ray.origin = {float(origin.x), float(origin.y), float(origin.z)};
  ray.direction = {float(-wo.x), float(-wo.y), float(-wo.z)};
  double sum = 0, sumSquares = 0;
  render::RayCounts counts;
  for (int s = 0; s < samples; ++s) {
    render::RandomStream random(1, 0, std::uint64_t(s));
    const double value = integrator.radiance(ray, random, counts).g;
    sum += value, sumSquares += value * value;
  }
  const double mean = sum / samples, variance = std::max(0.0, sumSquares / samples - mean * mean);
  // The samples are a stratified set, for which this overstates the error: a safe yardstick.
  return {mean, std::sqrt(variance / samples)};
}

TEST(LightSamplingTest, DiffusePlaneUnderAWideSunReflectsTheCosineWeightedCone) {
  const double albedo = 0.6, irradiance = 2, angle = 45, half = angle / 2 * kPi / 180;
  const double expected = albedo * irradiance * std::sin(half) * std::sin(half) / (2 * kPi * (1 - std::cos(half)));
  const Estimate estimate = planeUnderSun(R"({"type": "diffuse", "color": [0.6, 0.6, 0.6]})", V{0, 0, 1}, angle,
                                          irradiance, unit(V{0.3, -0.5, 1}), 1 << 16);
  EXPECT_NEAR(estimate.mean, expected, 4 * estimate.standardError) << "standard error " << estimate.standardError;
  EXPECT_GT(estimate.standardError, 0) << "both strategies vary: an exact answer would mean one is missing";
}

struct MetalCase {
  double roughness, angle, sunTilt, viewTilt;
};
void PrintTo(const MetalCase& c, std::ostream* out) {
  *out << "roughness " << c.roughness << ", sun " << c.angle << " deg wide, " << c.sunTilt
       << " deg from the normal, view " << c.viewTilt << " deg on the other side";
}

class GlossyUnderSunTest : public ::testing::TestWithParam<MetalCase> {};

TEST_P(GlossyUnderSunTest, MatchesTheMicrofacetIntegralOverTheCone) {
  const MetalCase c = GetParam();
  const double irradiance = 1.5, f0 = 0.9, alpha = c.roughness * c.roughness;
  const V towardsSun = tilted(c.sunTilt), wo = tilted(-c.viewTilt);
  const double expected = sunReflection(wo, towardsSun, c.angle / 2, irradiance, alpha, f0);
  const std::string metal =
      R"({"type": "metal", "color": [0.9, 0.9, 0.9], "roughness": )" + std::to_string(c.roughness) + "}";
  const Estimate estimate = planeUnderSun(metal, towardsSun, c.angle, irradiance, wo, 1 << 16);
  // The midpoint rule on 600 x 600 points: well under 1e-4 of the integral for these lobes.
  EXPECT_NEAR(estimate.mean, expected, 4 * estimate.standardError + 1e-4 * expected)
      << "standard error " << estimate.standardError << ", expected " << expected;
  EXPECT_GT(expected, 0.05) << "the case should reflect the sun";
}

// A rough lobe under a sun as wide as it (the strategies share the work), and a sharp lobe
// narrower than a small sun (BSDF sampling finds most of it), each seen near the mirror direction.
INSTANTIATE_TEST_SUITE_P(Lobes, GlossyUnderSunTest,
                         ::testing::Values(MetalCase{0.5, 30, 20, 25}, MetalCase{0.5, 30, 10, 50},
                                           MetalCase{0.1, 2, 30, 30}, MetalCase{0.1, 2, 30, 31}),
                         [](const ::testing::TestParamInfo<MetalCase>& info) {
                           return "case" + std::to_string(info.index);
                         });

}  // namespace
}  // namespace revolve
