#include "render/materials.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace revolve::render {

using namespace app;
// Declared here, beside Color's own operators, which would otherwise hide the directive's.
using app::operator+;
using app::operator-;
using app::operator*;

namespace {

constexpr float kPi = std::numbers::pi_v<float>;
// Below this alpha the GGX lobe is narrower than float directions can resolve: treat the metal as
// a perfect (Fresnel-weighted) reflector instead of dividing by a vanishing D.
constexpr float kSmoothAlpha = 1e-4f;
// Path regularisation's narrowest glossy lobe. pbrt-v4 doubles alpha within [0.1, 0.3]; raising it
// to 0.3 outright leaves a third fewer noise fireflies on many.json (measured in README, "Fireflies").
constexpr float kRegularizedAlpha = 0.3f;

Color toColor(const io::Rgb& c) { return {float(c[0]), float(c[1]), float(c[2])}; }

Color schlick(Color f0, float cosine) {
  const float m = std::pow(std::max(0.0f, 1.0f - cosine), 5.0f);
  return {f0.r + (1 - f0.r) * m, f0.g + (1 - f0.g) * m, f0.b + (1 - f0.b) * m};
}

// GGX (Trowbridge-Reitz) in the local frame (z = normal).
float ggxD(Vec3 h, float alpha) {
  const float a2 = alpha * alpha;
  const float c2 = h.z * h.z;
  const float d = c2 * (a2 - 1) + 1;
  return a2 / (kPi * d * d);
}
float smithLambda(Vec3 w, float alpha) {
  const float c2 = w.z * w.z;
  if (c2 >= 1) return 0;
  const float tan2 = (1 - c2) / c2;
  return 0.5f * (std::sqrt(1 + alpha * alpha * tan2) - 1);
}

// Heitz 2018, "Sampling the GGX distribution of visible normals".
Vec3 sampleVisibleNormal(Vec3 wo, float alpha, float u1, float u2) {
  const Vec3 vh = normalize(Vec3{alpha * wo.x, alpha * wo.y, wo.z});
  const float lengthSquared = vh.x * vh.x + vh.y * vh.y;
  const Vec3 t1 = lengthSquared > 0 ? (1.0f / std::sqrt(lengthSquared)) * Vec3{-vh.y, vh.x, 0} : Vec3{1, 0, 0};
  const Vec3 t2 = cross(vh, t1);
  const float r = std::sqrt(u1), phi = 2 * kPi * u2;
  const float p1 = r * std::cos(phi);
  float p2 = r * std::sin(phi);
  const float s = 0.5f * (1 + vh.z);
  p2 = (1 - s) * std::sqrt(std::max(0.0f, 1 - p1 * p1)) + s * p2;
  const Vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1 - p1 * p1 - p2 * p2)) * vh;
  return normalize(Vec3{alpha * nh.x, alpha * nh.y, std::max(0.0f, nh.z)});
}

Vec3 cosineHemisphere(float u1, float u2) {
  const float r = std::sqrt(u1), phi = 2 * kPi * u2;
  return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1 - u1))};
}

}  // namespace

Vec3 reflect(Vec3 wo, Vec3 n) { return 2 * dot(wo, n) * n - wo; }

float fresnelDielectric(float cosIncident, float eta) {
  if (eta == 1) return 0;
  const float sin2t = (1 - cosIncident * cosIncident) / (eta * eta);
  if (sin2t >= 1) return 1;
  const float cosT = std::sqrt(1 - sin2t);
  const float parallel = (eta * cosIncident - cosT) / (eta * cosIncident + cosT);
  const float perpendicular = (cosIncident - eta * cosT) / (cosIncident + eta * cosT);
  return 0.5f * (parallel * parallel + perpendicular * perpendicular);
}

Material::Material(const io::SceneMaterial& material)
    : type_(material.type),
      color_(toColor(material.color)),
      tint_(toColor(material.tint)),
      alpha_(float(material.roughness * material.roughness)),
      ior_(float(material.ior)) {}

Color Material::evaluate(Vec3 wo, Vec3 wi, Vec3 shading, Vec3 geometric) const {
  if (dot(wi, geometric) <= 0) return {};
  const float cosI = dot(wi, shading), cosO = dot(wo, shading);
  if (cosI <= 0 || cosO <= 0) return {};
  if (type_ == io::MaterialType::diffuse) return (cosI / kPi) * color_;
  if (type_ != io::MaterialType::metal || alpha_ < kSmoothAlpha) return {};
  const Frame frame(shading);
  const Vec3 o = frame.toLocal(wo), i = frame.toLocal(wi);
  const Vec3 h = normalize(o + i);
  const float g2 = 1 / (1 + smithLambda(o, alpha_) + smithLambda(i, alpha_));
  return (ggxD(h, alpha_) * g2 / (4 * cosO)) * schlick(color_, dot(o, h));
}

std::optional<ScatterSample> Material::sample(Vec3 wo, Vec3 shading, Vec3 geometric, bool outside,
                                              RandomStream& random) const {
  const auto [u1, u2] = random.next2D();
  ScatterSample s;
  switch (type_) {
    case io::MaterialType::diffuse: {
      const Vec3 local = cosineHemisphere(u1, u2);
      s.wi = Frame(shading).toWorld(local);
      s.weight = color_;
      s.pdf = local.z / kPi;
      break;
    }
    case io::MaterialType::metal: {
      if (alpha_ < kSmoothAlpha) {
        s.wi = reflect(wo, shading);
        s.weight = schlick(color_, dot(wo, shading));
        s.specular = true;
        break;
      }
      const Frame frame(shading);
      const Vec3 o = frame.toLocal(wo);
      if (o.z <= 0) return std::nullopt;
      const Vec3 h = sampleVisibleNormal(o, alpha_, u1, u2);
      const Vec3 i = reflect(o, h);
      if (i.z <= 0) return std::nullopt;
      s.wi = frame.toWorld(i);
      // f cos / pdf with pdf = G1(o) D(h) / (4 cos_o): F G2 / G1(o).
      const float lambdaO = smithLambda(o, alpha_), lambdaI = smithLambda(i, alpha_);
      s.weight = ((1 + lambdaO) / (1 + lambdaO + lambdaI)) * schlick(color_, dot(o, h));
      s.pdf = ggxD(h, alpha_) / ((1 + lambdaO) * 4 * o.z);
      break;
    }
    case io::MaterialType::mirror: {
      s.wi = reflect(wo, shading);
      s.weight = color_;
      s.specular = true;
      break;
    }
    case io::MaterialType::glass: {
      const Split split = glassSplit(wo, shading, outside);
      s.specular = true;
      if (!split.refracted || u1 < split.reflectance) {
        s.wi = reflect(wo, shading);
        s.weight = {1, 1, 1};
        if (dot(s.wi, geometric) * dot(wo, geometric) <= 0) return std::nullopt;
        return s;
      }
      s.wi = *split.refracted;
      s.weight = tint_;
      if (dot(s.wi, geometric) * dot(wo, geometric) >= 0) return std::nullopt;
      return s;
    }
  }
  if (dot(s.wi, geometric) <= 0) return std::nullopt;  // below the real surface: would leak light
  return s;
}

float Material::pdf(Vec3 wo, Vec3 wi, Vec3 shading) const {
  const float cosI = dot(wi, shading);
  if (cosI <= 0) return 0;
  if (type_ == io::MaterialType::diffuse) return cosI / kPi;
  if (type_ != io::MaterialType::metal || alpha_ < kSmoothAlpha) return 0;
  const Frame frame(shading);
  const Vec3 o = frame.toLocal(wo), i = frame.toLocal(wi);
  if (o.z <= 0) return 0;
  // Visible normals (Heitz 2018): D_o(h) = G1(o) max(0, o.h) D(h) / cos_o, and dwi = dh / (4 o.h).
  const Vec3 h = normalize(o + i);
  return ggxD(h, alpha_) / ((1 + smithLambda(o, alpha_)) * 4 * o.z);
}

Material Material::regularized() const {
  Material rough = *this;
  if (type_ == io::MaterialType::metal && alpha_ >= kSmoothAlpha) rough.alpha_ = std::max(alpha_, kRegularizedAlpha);
  return rough;
}

Color Material::specularReflectance(Vec3 wo, Vec3 shading) const {
  if (type_ == io::MaterialType::mirror) return color_;
  if (type_ == io::MaterialType::metal) return schlick(color_, dot(wo, shading));
  return {};
}

Color Material::straightTransmittance(float cosine) const {
  if (type_ != io::MaterialType::glass) return {};
  return (1 - fresnelDielectric(std::min(cosine, 1.0f), ior_)) * tint_;
}

Material::Split Material::glassSplit(Vec3 wo, Vec3 shading, bool outside) const {
  // Work with the normal on wo's side; eta = n_transmitted / n_incident.
  const Vec3 n = dot(wo, shading) >= 0 ? shading : -shading;
  const float eta = outside ? ior_ : 1 / ior_;
  const float cosI = std::min(1.0f, std::abs(dot(wo, shading)));
  const float reflectance = fresnelDielectric(cosI, eta);
  if (reflectance >= 1) return {1, std::nullopt};
  if (eta == 1) return {0, -wo};  // straight through, not even rounded
  const float sin2t = (1 - cosI * cosI) / (eta * eta);
  const float cosT = std::sqrt(std::max(0.0f, 1 - sin2t));
  const Vec3 refracted = normalize((-1 / eta) * wo + (cosI / eta - cosT) * n);
  return {reflectance, refracted};
}

}  // namespace revolve::render
