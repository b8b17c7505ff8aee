// The scene's materials as scattering functions: diffuse (Lambert), metal (GGX microfacet with
// Schlick's Fresnel to the metal's colour, sampled by visible normals so that a sample's weight
// F G1 never exceeds 1), mirror (perfect reflection) and glass (exact dielectric Fresnel,
// refraction, total internal reflection, an optional tint per crossing of the surface).
//
// Directions are unit world vectors pointing away from the surface: wo towards the viewer, wi
// towards the light. `shading` is the smooth shading normal, `geometric` the surface's own normal,
// both already turned to wo's side (except for glass, which needs to know which side it is on).
#pragma once

#include "geometry/vector_math.h"
#include "io/scene_file.h"
#include "render/color.h"
#include "render/random_stream.h"

#include <optional>

namespace revolve::render {

struct ScatterSample {
  Vec3 wi{};
  Color weight;           // f cos(theta_i) / pdf: the factor the path's throughput takes
  bool specular = false;  // a delta lobe: lights cannot be sampled for it
  float pdf = 0;          // solid-angle density of wi (pdf() of it); 0 for a delta lobe
};

class Material {
 public:
  explicit Material(const io::SceneMaterial& material);

  io::MaterialType type() const { return type_; }
  // Whether the material has a lobe that light sampling can reach (diffuse, metal).
  bool hasSmoothLobe() const { return type_ == io::MaterialType::diffuse || type_ == io::MaterialType::metal; }
  // f(wo, wi) cos(theta_i) of the non-delta lobe; black for mirror and glass, and for wi below the
  // geometric surface.
  Color evaluate(Vec3 wo, Vec3 wi, Vec3 shading, Vec3 geometric) const;
  // The solid-angle density with which sample() draws wi (0 for the delta lobes of mirror, glass
  // and smooth metal): what multiple importance sampling weighs light samples against.
  float pdf(Vec3 wo, Vec3 wi, Vec3 shading) const;
  // Draws wi from the material. Nothing when the sample is absorbed or points into the surface.
  // Glass: `outside` says whether wo lies on the side the surface's own normal points to.
  std::optional<ScatterSample> sample(Vec3 wo, Vec3 shading, Vec3 geometric, bool outside, RandomStream& random) const;

  // Perfect reflection and refraction, for the Whitted integrator: the mirror's colour, or Schlick's
  // Fresnel at normal incidence from the metal's colour; glass splits by Fresnel.
  Color specularReflectance(Vec3 wo, Vec3 shading) const;
  struct Split {
    float reflectance;              // Fresnel: the rest is transmitted (times the tint)
    std::optional<Vec3> refracted;  // none under total internal reflection
  };
  Split glassSplit(Vec3 wo, Vec3 shading, bool outside) const;
  // Glass: the tint times the Fresnel transmission (from outside) at this cosine, for light that
  // crosses the surface on a straight line (filtered shadows); black for the other kinds.
  Color straightTransmittance(float cosine) const;
  // Path regularisation (as pbrt-v4's BSDF::Regularize): a glossy metal narrower than alpha = 0.3
  // widened to 0.3. Applied after a path's first diffuse or glossy bounce, where a narrow lobe lit
  // by a small light is found only by chance and makes fireflies. Other kinds are unchanged: delta
  // lobes (mirror, glass, smooth metal) stay delta.
  Material regularized() const;
  Color tint() const { return tint_; }
  Color color() const { return color_; }

 private:
  io::MaterialType type_;
  Color color_, tint_;
  float alpha_ = 0;  // GGX alpha = roughness^2
  float ior_ = 1;
};

Vec3 reflect(Vec3 wo, Vec3 n);
// Exact Fresnel reflectance of a dielectric interface, cos_i > 0 on the incident side and eta =
// n_transmitted / n_incident; 1 under total internal reflection, exactly 0 for eta = 1.
float fresnelDielectric(float cosIncident, float eta);

}  // namespace revolve::render
