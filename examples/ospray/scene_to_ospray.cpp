#include "scene_to_ospray.h"

#include "embree/tessellation.h"
#include "geometry/placement.h"

#include <ospray/ospray_util.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace revolve::ospray_example {

namespace {

// An OSPRay-owned copy: OSPRay reads shared arrays when it uses them, after these vectors go.
OSPData copied(const void* items, OSPDataType type, std::size_t count) {
  OSPData shared = ospNewSharedData(items, type, count);
  OSPData copy = ospNewData(type, count);
  ospCopyData(shared, copy);
  ospRelease(shared);
  return copy;
}

std::array<float, 3> asFloat3(const app::Vec3d& v) { return {float(v[0]), float(v[1]), float(v[2])}; }

// An RGB quantity as OSPRay's light takes it: a colour (largest channel 1) and an intensity.
void setColorAndIntensity(OSPLight light, const io::Rgb& rgb) {
  const double largest = std::max({rgb[0], rgb[1], rgb[2]});
  const std::array<float, 3> color =
      largest > 0 ? std::array<float, 3>{float(rgb[0] / largest), float(rgb[1] / largest), float(rgb[2] / largest)}
                  : std::array<float, 3>{1, 1, 1};
  ospSetParam(light, "color", OSP_VEC3F, color.data());
  ospSetFloat(light, "intensity", float(largest));
}

}  // namespace

OSPObject OsprayScene::keep(OSPObject object) {
  owned_.push_back(object);
  return object;
}

OSPGeometry newMesh(const Profile& profile, std::uint32_t slices, std::size_t& bytes) {
  const detail::TriangleMesh mesh = detail::tessellate(profile, slices);
  OSPGeometry geometry = ospNewGeometry("mesh");
  OSPData vertices = copied(mesh.vertices.data(), OSP_VEC3F, mesh.vertices.size() / 3);
  OSPData indices = copied(mesh.indices.data(), OSP_VEC3UI, mesh.indices.size() / 3);
  ospSetObject(geometry, "vertex.position", vertices);
  ospSetObject(geometry, "index", indices);
  ospRelease(vertices);
  ospRelease(indices);
  ospCommit(geometry);
  bytes += mesh.vertices.size() * sizeof(float) + mesh.indices.size() * sizeof(std::uint32_t);
  return geometry;
}

OsprayScene::OsprayScene(const io::SceneDescription& scene, int width, int height, std::uint32_t meshSlices) {
  // Materials: "obj" (OSPRay's Wavefront material, understood by scivis and the path tracer).
  std::vector<OSPMaterial> materials;
  for (const io::SceneMaterial& m : scene.materials) {
    OSPMaterial material = ospNewMaterial("obj");
    const std::array<float, 3> color = {float(m.color[0]), float(m.color[1]), float(m.color[2])};
    const std::array<float, 3> black = {0, 0, 0};
    const bool specular = m.type == io::MaterialType::metal || m.type == io::MaterialType::mirror;
    ospSetParam(material, "kd", OSP_VEC3F, specular ? black.data() : color.data());
    if (specular) {
      ospSetParam(material, "ks", OSP_VEC3F, color.data());
      ospSetFloat(material, "ns",
                  m.type == io::MaterialType::mirror ? 1000.0f : float(2.0 / std::max(1e-3, m.roughness)));
    }
    if (m.type == io::MaterialType::glass) {
      const std::array<float, 3> tint = {float(m.tint[0]), float(m.tint[1]), float(m.tint[2])};
      ospSetParam(material, "tf", OSP_VEC3F, tint.data());
      ospSetFloat(material, "d", 0.2f);
    }
    ospCommit(material);
    materials.push_back(OSPMaterial(keep(material)));
  }

  // One "revolution" geometry per profile, shared by the objects that use it.
  std::vector<OSPGeometry> revolutions;
  for (const io::SceneProfile& p : scene.profiles) {
    if (meshSlices > 0) {
      revolutions.push_back(OSPGeometry(keep(newMesh(p.polyline(), meshSlices, geometryBytes_))));
      continue;
    }
    OSPGeometry geometry = ospNewGeometry("revolution");
    std::vector<float> points;
    const char* spline = nullptr;
    if (p.curve && p.curve->kind() != SplineKind::linear) {
      for (const Point2& q : p.curve->points()) points.insert(points.end(), {float(q.r), float(q.z)});
      spline = splineKindName(p.curve->kind());
      // A tolerance: the module traces the curve's polyline within it, shaded with the curve's normals.
      if (p.tolerance > 0) ospSetFloat(geometry, "tolerance", float(p.tolerance));
    } else {
      for (const Point2& q : p.polyline().points()) points.insert(points.end(), {float(q.r), float(q.z)});
    }
    OSPData data = copied(points.data(), OSP_VEC2F, points.size() / 2);
    ospSetObject(geometry, "profile", data);
    ospRelease(data);
    if (spline != nullptr)
      ospSetParam(geometry, "spline", OSP_STRING, spline);  // not ospSetString: OSPRay 3.2's passes &s
    ospCommit(geometry);
    revolutions.push_back(OSPGeometry(keep(geometry)));
    // The same shape the module builds (a spline traced exactly, or the polyline), for its size;
    // for a curve traced as its polyline, also the curve's normals and the segments' starts it keeps.
    geometryBytes_ += p.spline ? Shape(*p.spline).memoryBytes() : Shape(*p.profile).memoryBytes();
    if (!p.spline && p.curve && p.curve->kind() != SplineKind::linear) {
      const ShadingNormals normals(p.polyline(), *p.curve);
      geometryBytes_ += normals.memoryBytes() + normals.segmentCount() * sizeof(float);
    }
  }

  const auto addInstance = [&](OSPGeometry geometry, std::size_t material, const float* affine) {
    OSPGeometricModel model = ospNewGeometricModel(geometry);
    ospSetObject(model, "material", materials[material]);
    ospCommit(model);
    keep(model);
    OSPGroup group = ospNewGroup();
    OSPData models = copied(&model, OSP_GEOMETRIC_MODEL, 1);
    ospSetObject(group, "geometry", models);
    ospRelease(models);
    ospCommit(group);
    keep(group);
    OSPInstance instance = ospNewInstance(group);
    // Its index as OSPRay's instance id (the OSP_FB_ID_INSTANCE channel): the scene's object
    // numbering, quads after the objects, as revolve-render's picking counts them.
    ospSetInt(instance, "id", int(instances_.size()));
    if (affine != nullptr) ospSetParam(instance, "transform", OSP_AFFINE3F, affine);
    ospCommit(instance);
    instances_.push_back(OSPInstance(keep(instance)));
  };
  for (const io::SceneObject& object : scene.objects) {
    // OSPRay's affine3f: the linear part's columns, then the translation.
    const app::Matrix3d linear = app::linearPart(object.transform);
    std::array<float, 12> affine{};
    for (int column = 0; column < 3; ++column) {
      for (int row = 0; row < 3; ++row) affine[3 * column + row] = float(linear[row][column]);
    }
    for (int row = 0; row < 3; ++row) affine[9 + row] = float(object.transform.translate[row]);
    addInstance(revolutions[object.profile], object.material, affine.data());
  }
  // Each quad its own mesh (a material apiece), in world space.
  for (const io::SceneQuad& quad : scene.quads) {
    OSPGeometry mesh = ospNewGeometry("mesh");
    std::vector<float> corners;
    for (const app::Vec3d& c : quad.corners) {
      const auto f = asFloat3(c);
      corners.insert(corners.end(), f.begin(), f.end());
    }
    const std::array<std::uint32_t, 4> index = {0, 1, 2, 3};
    OSPData vertices = copied(corners.data(), OSP_VEC3F, 4);
    OSPData indices = copied(index.data(), OSP_VEC4UI, 1);
    ospSetObject(mesh, "vertex.position", vertices);
    ospSetObject(mesh, "index", indices);
    ospRelease(vertices);
    ospRelease(indices);
    ospCommit(mesh);
    addInstance(OSPGeometry(keep(mesh)), quad.material, nullptr);
  }

  std::vector<OSPLight> lights;
  for (const io::SceneLight& l : scene.lights) {
    OSPLight light;
    if (l.type == io::LightType::point) {
      light = ospNewLight("sphere");
      const auto position = asFloat3(l.position);
      ospSetParam(light, "position", OSP_VEC3F, position.data());
      ospSetInt(light, "intensityQuantity", OSP_INTENSITY_QUANTITY_INTENSITY);
      setColorAndIntensity(light, l.intensity);
    } else {
      light = ospNewLight("distant");
      const auto direction = asFloat3(l.direction);
      ospSetParam(light, "direction", OSP_VEC3F, direction.data());
      ospSetFloat(light, "angularDiameter", float(l.angleDegrees));
      ospSetInt(light, "intensityQuantity", OSP_INTENSITY_QUANTITY_IRRADIANCE);
      setColorAndIntensity(light, l.irradiance);
    }
    ospCommit(light);
    lights.push_back(OSPLight(keep(light)));
  }
  // The environment as OSPRay's ambient light: a sky by its mean of zenith and horizon.
  {
    const io::SceneEnvironment& e = scene.environment;
    const io::Rgb radiance = e.sky ? io::Rgb{(e.zenith[0] + e.horizon[0]) / 2, (e.zenith[1] + e.horizon[1]) / 2,
                                             (e.zenith[2] + e.horizon[2]) / 2}
                                   : e.color;
    OSPLight ambient = ospNewLight("ambient");
    ospSetInt(ambient, "intensityQuantity", OSP_INTENSITY_QUANTITY_RADIANCE);
    setColorAndIntensity(ambient, radiance);
    ospCommit(ambient);
    lights.push_back(OSPLight(keep(ambient)));
  }

  world_ = ospNewWorld();
  OSPData instanceData = copied(instances_.data(), OSP_INSTANCE, instances_.size());
  OSPData lightData = copied(lights.data(), OSP_LIGHT, lights.size());
  ospSetObject(world_, "instance", instanceData);
  ospSetObject(world_, "light", lightData);
  ospRelease(instanceData);
  ospRelease(lightData);
  ospCommit(world_);

  camera_ = ospNewCamera("perspective");
  const io::SceneCamera& c = scene.camera;
  const auto position = asFloat3(c.from);
  const std::array<float, 3> direction = {float(c.to[0] - c.from[0]), float(c.to[1] - c.from[1]),
                                          float(c.to[2] - c.from[2])};
  const auto up = asFloat3(c.up);
  ospSetParam(camera_, "position", OSP_VEC3F, position.data());
  ospSetParam(camera_, "direction", OSP_VEC3F, direction.data());
  ospSetParam(camera_, "up", OSP_VEC3F, up.data());
  ospSetFloat(camera_, "fovy", float(c.fovDegrees));
  ospSetFloat(camera_, "aspect", float(width) / float(height));
  ospCommit(camera_);
}

OsprayScene::~OsprayScene() {
  if (camera_ != nullptr) ospRelease(camera_);
  if (world_ != nullptr) ospRelease(world_);
  for (OSPObject object : owned_) ospRelease(object);
}

}  // namespace revolve::ospray_example
