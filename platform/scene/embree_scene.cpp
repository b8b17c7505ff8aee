#include "scene/embree_scene.h"

#include <revolve/embree_baselines.h>

#include "embree/embree_rays.h"
#include "embree/memory_check.h"
#include "geometry/placement.h"
#include "geometry/ray_limits.h"
#include "geometry/vector_math.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace revolve::scene {

using app::operator+;  // geometry/vector_math.h
using app::operator-;
using app::operator*;

namespace {

constexpr double kUnitRoundoff = 0x1p-24;  // float's u
// pbrt-v4's gamma(n) = n u / (1 - n u): the relative error bound of n float operations.
constexpr double gamma(int n) { return n * kUnitRoundoff / (1 - n * kUnitRoundoff); }

float awayFrom(float value, float offset) {
  if (offset > 0) return std::nextafter(value, std::numeric_limits<float>::infinity());
  if (offset < 0) return std::nextafter(value, -std::numeric_limits<float>::infinity());
  return value;
}

// Moves p along unit n by `distance` to the side `direction` lies on, rounding away from p so
// that rounding cannot undo the move (as pbrt-v4's OffsetRayOrigin).
Vec3 pushAlongNormal(Vec3 p, Vec3 n, float distance, Vec3 direction) {
  if (app::dot(n, direction) < 0) distance = -distance;
  const Vec3 offset = distance * n;
  return {awayFrom(p.x + offset.x, offset.x), awayFrom(p.y + offset.y, offset.y), awayFrom(p.z + offset.z, offset.z)};
}

// The distance from `local` (object space) to the profile segment's surface, in double precision.
double distanceToSegment(const Profile& profile, std::uint32_t segment, Vec3 local) {
  const Point2 a = profile.points()[segment], b = profile.points()[segment + 1];
  const double rho = std::hypot(double(local.x), double(local.y));
  const double er = b.r - a.r, ez = b.z - a.z;
  const double along = std::clamp(((rho - a.r) * er + (local.z - a.z) * ez) / (er * er + ez * ez), 0.0, 1.0);
  return std::hypot(rho - (a.r + along * er), local.z - (a.z + along * ez));
}

// revolve's u and v (Conventions) of an object-space point on (or next to) a profile segment.
std::pair<float, float> surfaceParameters(const Profile& profile, std::uint32_t segment, Vec3 local) {
  const double uTurns = std::atan2(double(local.y), double(local.x)) * (0.5 / std::numbers::pi);
  const float u = float(uTurns < 0 ? uTurns + 1 : uTurns);
  const Point2 a = profile.points()[segment], b = profile.points()[segment + 1];
  const double rho = std::hypot(double(local.x), double(local.y));
  const double er = b.r - a.r, ez = b.z - a.z;
  const double along = std::clamp(((rho - a.r) * er + (local.z - a.z) * ez) / (er * er + ez * ez), 0.0, 1.0);
  const std::span<const double> arc = profile.arcLength();
  return {u, float((arc[segment] + along * (arc[segment + 1] - arc[segment])) / arc.back())};
}

// The ray with a unit direction, t scaled to match (tfar = inf stays inf); returns |d|, by which
// the t Embree returns is divided to come back to the caller's units.
float normaliseDirection(RTCRay& ray) noexcept {
  const float length = std::sqrt(ray.dir_x * ray.dir_x + ray.dir_y * ray.dir_y + ray.dir_z * ray.dir_z);
  ray.dir_x /= length;
  ray.dir_y /= length;
  ray.dir_z /= length;
  ray.tnear *= length;
  ray.tfar *= length;
  return length;
}

}  // namespace

namespace {

// A polyline made from a curve shades with the curve's own normals (a coarse polyline then looks
// like the curve); any other profile with normals interpolated between its vertices.
ShadingNormals shadingNormalsOf(const io::SceneProfile& source) {
  const Profile& polyline = source.polyline();
  if (source.curve && !polyline.curveParameters().empty()) return ShadingNormals(polyline, *source.curve);
  return ShadingNormals(polyline, source.creaseDegrees);
}

}  // namespace

// One profile built into Embree, whichever objects show it.
struct EmbreeScene::Prototype {
  // What a mesh or Embree's cone curve holds, apart: an exact surface, of which a scene may hold a
  // million, pays 8 bytes for it.
  struct Approximation {
    Profile profile;  // the polyline meshed or traced as cones
    std::optional<ConeCurveGeometry> cone;
    RTCGeometry mesh = nullptr;  // retained while the prototype lives
    const float* meshVertices = nullptr;
    const std::uint32_t* meshIndices = nullptr;
    std::uint32_t slices = 0;
    app::Scene scene;  // which the objects instance
    explicit Approximation(Profile polyline) : profile(std::move(polyline)) {}
    ~Approximation() {
      scene.reset();
      if (mesh != nullptr) rtcReleaseGeometry(mesh);
    }
    Approximation(const Approximation&) = delete;
    Approximation& operator=(const Approximation&) = delete;
  };

  std::optional<Shape> shape;                     // traced exactly
  std::unique_ptr<const ShadingNormals> normals;  // a scene file's profiles: smooth shading
  // A mesh or cone curve (none for an exact surface). An exact surface has no scene of its own:
  // each of its objects is a placed revolve::Geometry (Instance::exact).
  std::unique_ptr<Approximation> approximation;

  // A scene file's profile, as `settings` build it. An exact surface keeps no copy of the polyline
  // (its shape holds it), and an exact spline no shading normals (its geometric normal is smooth
  // already): a scene of a million objects pays for neither.
  Prototype(const io::SceneProfile& source, RTCDevice device, const BuildSettings& settings) {
    const bool exact = !settings.mesh && !settings.embreeCone;
    if (!exact || !source.spline) normals = std::make_unique<const ShadingNormals>(shadingNormalsOf(source));
    if (exact) {
      if (source.spline) {
        shape.emplace(*source.spline, settings.options);  // the curve itself, its normals smooth already
      } else {
        shape.emplace(*source.profile, settings.options);
      }
      return;
    }
    approximation = std::make_unique<Approximation>(source.polyline());
    Approximation& a = *approximation;
    a.scene = app::newScene(device);
    if (settings.mesh) {
      a.slices = settings.slices;
      a.mesh = newTessellatedGeometry(device, a.profile, a.slices);
      a.meshVertices = static_cast<const float*>(rtcGetGeometryBufferData(a.mesh, RTC_BUFFER_TYPE_VERTEX, 0));
      a.meshIndices = static_cast<const std::uint32_t*>(rtcGetGeometryBufferData(a.mesh, RTC_BUFFER_TYPE_INDEX, 0));
      if (a.meshVertices == nullptr || a.meshIndices == nullptr)
        throw std::runtime_error("Embree gave no mesh buffers");
      rtcAttachGeometry(a.scene.get(), a.mesh);
    } else {
      a.cone.emplace(device, a.profile);
      rtcAttachGeometry(a.scene.get(), a.cone->handle());
    }
    rtcCommitScene(a.scene.get());
  }
  // A shape traced exactly.
  explicit Prototype(Shape traced) : shape(std::move(traced)) {}

  const ConeCurveGeometry* cone() const noexcept {
    return approximation && approximation->cone ? &*approximation->cone : nullptr;
  }
  // The profile's polyline for recovering segments, u and v from a point (meshes, cone curves).
  const Profile& polyline() const { return approximation ? approximation->profile : shape->profile(); }
};

// An object: a prototype where its placement puts it.
struct EmbreeScene::Instance {
  std::uint32_t id = 0, prototype = 0, material = 0;
  float reflectivity = 1;
  app::Placement placement;
  // An exact surface: its shape as an Embree geometry placed where the object is (unplaced for the
  // identity), attached to the top scene under the object's id; and the same again with
  // filteredScene()'s filter. An Embree instance of a one-geometry scene would cost each object
  // about 4 KB and each ray a second traversal.
  std::optional<revolve::Geometry> exact, filtered;
  bool worldNormals = false;  // the identity: hits' normals are the world's already
  // What a hit needs of the placement, as Embree holds it: the linear part rounded to float, the
  // inverse transpose of that for normals, the translation in float.
  app::Matrix3d linear{}, normalMatrix{};
  std::array<float, 9> rangeNormalMatrix{};  // normalMatrix rounded to float, row by row: a range hit's normal
  Vec3 translate{};
  // The world ray is mapped into object space: o' = L^-1 (o - T), d' = L^-1 d, each component
  // within gamma(3) of |L^-1| (|o| + |T|) and |L^-1| |d| (as Embree's instance maps it in float;
  // revolve::Geometry's placement maps it in double and rounds once, well within that). Mapped back
  // through L, the exact hit of that ray lies within gamma(3) |L| |L^-1| (|o| + |T| + |t d|) of the
  // world ray's (infinity norms); this is that factor, gamma(3) |L| |L^-1|, with room (gamma(4)).
  float transformErrorFactor = 0;
};

EmbreeScene::EmbreeScene(const Layout& layout, bool unitDirections)
    : memory_(std::make_unique<app::EmbreeMemory>()),
      device_(app::newDevice()),
      layout_(layout),
      unitDirections_(unitDirections) {
  app::monitorMemory(device_.get(), memory_.get());
  top_ = app::newScene(device_.get());
  if (layout.robust) rtcSetSceneFlags(top_.get(), RTC_SCENE_FLAG_ROBUST);
}

EmbreeScene::EmbreeScene(const Layout& layout) : EmbreeScene(layout, false) {}

EmbreeScene::EmbreeScene(const io::SceneDescription& description, const BuildSettings& settings)
    : EmbreeScene(Layout{}, settings.embreeCone) {
  const auto start = std::chrono::steady_clock::now();
  countStats_ = settings.countStats;
  const auto objectName = [&](std::size_t i) {
    const io::SceneObject& object = description.objects[i];
    return description.file + ": objects[" + std::to_string(i) + "]" +
           (object.name.empty() ? "" : " \"" + object.name + "\"");
  };
  if (settings.mesh || settings.embreeCone) io::drawPolylines(description);  // every one is read below
  if (settings.embreeCone) {
    for (std::size_t i = 0; i < description.objects.size(); ++i) {
      const io::SceneObject& object = description.objects[i];
      const io::SceneProfile& profile = description.profiles[object.profile];
      // A profile made from a curve is traced as its polyline: its points are that polyline's, not
      // the scene's, and the message says so.
      const bool fromCurve = profile.spline || profile.tolerance > 0;
      std::string which = objectName(i) + " (profiles." + profile.name;
      if (fromCurve) {
        double size = 0;  // as the scene reader measures a spline (io::SceneProfile::kDrawingFraction)
        if (profile.spline) {
          for (const Point2& p : profile.spline->bezier()) size = std::max({size, std::abs(p.r), std::abs(p.z)});
        }
        const double within = profile.tolerance > 0 ? profile.tolerance : io::SceneProfile::kDrawingFraction * size;
        char text[32];
        std::snprintf(text, sizeof text, "%.3g", within);
        which += std::string(", a curve traced as its polyline within ") + text;
      }
      which += ")";
      if (std::optional<std::string> limitation =
              coneCurveLimitation(profile.polyline(), fromCurve ? "polyline point" : "profile point")) {
        throw std::runtime_error(which + " cannot be traced as Embree's linear cone curve: " + *limitation);
      }
      const app::Vec3d& scale = object.transform.scale;
      if (scale[0] != 1 || scale[1] != 1 || scale[2] != 1) {
        char text[96];
        std::snprintf(text, sizeof text, "%.9g, %.9g, %.9g", scale[0], scale[1], scale[2]);
        throw std::runtime_error(which + " is scaled by (" + text +
                                 "): Embree's linear cone curve kernel assumes unit ray directions, and an instance's "
                                 "scale changes their length in object space; scale its profile's points instead");
      }
    }
  }

  // Each profile used by an object is built once (in parallel: shapes are independent).
  std::vector<std::int64_t> prototypeOf(description.profiles.size(), -1);
  std::vector<std::size_t> used;
  for (const io::SceneObject& object : description.objects) {
    if (prototypeOf[object.profile] < 0) {
      prototypeOf[object.profile] = std::int64_t(used.size());
      used.push_back(object.profile);
    }
  }
  if (settings.mesh) {
    double triangles = 0;
    for (const std::size_t profile : used)
      triangles += 2.0 * double(description.profiles[profile].polyline().segmentCount()) * settings.slices;
    app::requireMemory(triangles * app::kMeshBytesPerTriangle,
                       "--geometry mesh with " + std::to_string(settings.slices) + " slices (" +
                           std::to_string(std::uint64_t(triangles)) + " triangles)");
  }
  prototypes_.resize(used.size());
  tbb::parallel_for(std::size_t{0}, used.size(), [&](std::size_t i) {
    prototypes_[i] = std::make_unique<Prototype>(description.profiles[used[i]], device_.get(), settings);
  });

  // The objects' records and Embree geometries made in parallel, then attached in order; of
  // objects that cannot be placed, the first is named.
  instances_.resize(description.objects.size());
  std::vector<std::exception_ptr> faults(description.objects.size());
  tbb::parallel_for(std::size_t{0}, description.objects.size(), [&](std::size_t i) {
    const io::SceneObject& object = description.objects[i];
    try {
      // The reader holds transforms to the placement rule; held again here for descriptions made in code.
      const app::Placement placement(object.transform);
      instances_[i] = newInstance(std::uint32_t(i), std::uint32_t(prototypeOf[object.profile]), placement,
                                  std::uint32_t(object.material), float(object.reflectivity));
    } catch (const std::exception& error) {  // the placement rule, or Embree refusing the geometry
      faults[i] = std::make_exception_ptr(std::runtime_error(objectName(i) + ": " + error.what()));
    } catch (...) {
      faults[i] = std::current_exception();
    }
  });
  for (const std::exception_ptr& fault : faults) {
    if (fault) std::rethrow_exception(fault);
  }
  faults = {};
  geometries_.reserve(description.objects.size() + (description.quads.empty() ? 0 : 1));
  for (std::size_t i = 0; i < description.objects.size(); ++i) attach(i);

  if (!description.quads.empty()) {
    TriangleMesh quads;
    for (std::size_t q = 0; q < description.quads.size(); ++q) {
      const io::SceneQuad& quad = description.quads[q];
      for (const app::Vec3d& corner : quad.corners) {
        for (const double x : corner) quads.vertices.push_back(float(x));
      }
      const auto base = std::uint32_t(4 * q);
      for (const std::uint32_t k : {base, base + 1, base + 2, base, base + 2, base + 3}) quads.triangles.push_back(k);
      quads.quadMaterials.push_back(std::uint32_t(quad.material));
      quads.quadReflectivities.push_back(float(quad.reflectivity));
    }
    quads.vertices.push_back(0);
    addMesh(std::move(quads));
  }
  commit();
  buildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

EmbreeScene::~EmbreeScene() {
  top_.reset();
  filtered_.reset();
  prototypes_.clear();
}

std::uint32_t EmbreeScene::addRevolution(Shape shape, const app::Placement& placement, std::uint32_t material) {
  if (geometries_.size() >= RTC_INVALID_GEOMETRY_ID)
    throw std::length_error("a scene holds at most 2^32 - 1 geometries");
  prototypes_.push_back(std::make_unique<Prototype>(std::move(shape)));
  try {
    return addInstance(std::uint32_t(prototypes_.size() - 1), placement, material);
  } catch (...) {
    prototypes_.pop_back();  // nothing added
    throw;
  }
}

std::uint32_t EmbreeScene::addRevolutions(std::vector<Shape> shapes, std::span<const app::Placement> placements) {
  if (shapes.size() != placements.size()) throw std::invalid_argument("addRevolutions: a placement for every shape");
  if (geometries_.size() + shapes.size() >= RTC_INVALID_GEOMETRY_ID)
    throw std::length_error("a scene holds at most 2^32 - 1 geometries");
  const std::size_t first = prototypes_.size();
  const auto firstId = std::uint32_t(geometries_.size());
  // The objects' records and Embree geometries made in parallel, then attached in order.
  const std::size_t firstInstance = instances_.size();
  try {
    prototypes_.reserve(first + shapes.size());
    for (Shape& shape : shapes) prototypes_.push_back(std::make_unique<Prototype>(std::move(shape)));
    instances_.resize(firstInstance + shapes.size());
    tbb::parallel_for(std::size_t{0}, shapes.size(), [&](std::size_t i) {
      instances_[firstInstance + i] =
          newInstance(firstId + std::uint32_t(i), std::uint32_t(first + i), placements[i], 0, 1);
    });
  } catch (...) {
    instances_.resize(firstInstance);  // nothing added
    prototypes_.resize(first);
    throw;
  }
  geometries_.reserve(geometries_.size() + shapes.size());
  for (std::size_t i = 0; i < shapes.size(); ++i) attach(firstInstance + i);
  return firstId;
}

std::uint32_t EmbreeScene::addInstance(std::uint32_t prototype, const app::Placement& placement, std::uint32_t material,
                                       float reflectivity) {
  instances_.push_back(newInstance(std::uint32_t(geometries_.size()), prototype, placement, material, reflectivity));
  return attach(instances_.size() - 1);
}

EmbreeScene::Instance EmbreeScene::newInstance(std::uint32_t id, std::uint32_t prototype,
                                               const app::Placement& placement, std::uint32_t material,
                                               float reflectivity) const {
  Instance instance;
  instance.id = id;
  instance.prototype = prototype;
  instance.material = material;
  instance.reflectivity = reflectivity;
  instance.placement = placement;
  instance.linear = app::roundedToFloat(placement.linear());  // the floats Embree will use
  const app::Matrix3d inv = app::inverse(instance.linear);
  instance.normalMatrix = inv.transposed();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) instance.rangeNormalMatrix[std::size_t(3 * r + c)] = float(instance.normalMatrix[r][c]);
  }
  const app::Vec3d& t = placement.translate();
  instance.translate = {float(t[0]), float(t[1]), float(t[2])};
  instance.transformErrorFactor = float(gamma(4) * instance.linear.infinityNorm() * inv.infinityNorm());
  const Prototype& built = *prototypes_[prototype];
  if (built.shape) {
    instance.worldNormals = placement.isIdentity();
    instance.exact = exactGeometry(*built.shape, instance);
  }
  return instance;
}

std::uint32_t EmbreeScene::attach(std::size_t index) {
  const Instance& instance = instances_[index];
  const std::uint32_t id = instance.id;
  if (instance.exact) {
    rtcAttachGeometryByID(top_.get(), instance.exact->handle(), id);
  } else {
    RTCGeometry geometry = rtcNewGeometry(device_.get(), RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(geometry, prototypes_[instance.prototype]->approximation->scene.get());
    const std::array<float, 12> columns = instance.placement.embreeColumns();
    rtcSetGeometryTransform(geometry, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, columns.data());
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(top_.get(), geometry, id);
    rtcReleaseGeometry(geometry);
  }
  geometries_.push_back({false, std::uint32_t(index)});
  filteredCurrent_ = false;
  return id;
}

std::uint32_t EmbreeScene::addTriangles(std::span<const float> vertices, std::span<const std::uint32_t> triangles) {
  TriangleMesh mesh;
  mesh.vertices.reserve(vertices.size() + 1);
  mesh.vertices.assign(vertices.begin(), vertices.end());
  mesh.vertices.push_back(0);
  mesh.triangles.assign(triangles.begin(), triangles.end());
  return addMesh(std::move(mesh));
}

namespace {

// A triangle geometry over `mesh`'s arrays (shared: they stay where they are).
RTCGeometry newTriangles(RTCDevice device, const TriangleMesh& mesh) {
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, mesh.vertices.data(), 0,
                             3 * sizeof(float), mesh.vertexCount());
  rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh.triangles.data(), 0,
                             3 * sizeof(std::uint32_t), mesh.triangleCount());
  return geometry;
}

}  // namespace

std::uint32_t EmbreeScene::addMesh(TriangleMesh mesh) {
  if (geometries_.size() >= RTC_INVALID_GEOMETRY_ID)
    throw std::length_error("a scene holds at most 2^32 - 1 geometries");
  const auto id = std::uint32_t(geometries_.size());
  meshes_.push_back(std::move(mesh));
  RTCGeometry geometry = newTriangles(device_.get(), meshes_.back());
  rtcCommitGeometry(geometry);
  rtcAttachGeometryByID(top_.get(), geometry, id);
  rtcReleaseGeometry(geometry);
  geometries_.push_back({true, std::uint32_t(meshes_.size() - 1)});
  filteredCurrent_ = false;
  return id;
}

void EmbreeScene::commit() {
  rtcCommitScene(top_.get());
  if (rtcGetDeviceError(device_.get()) != RTC_ERROR_NONE) throw std::runtime_error("Embree failed to build the scene");
}

const Shape* EmbreeScene::shapeOf(std::uint32_t id) const noexcept {
  const Geometry& g = geometries_[id];
  if (g.mesh) return nullptr;
  const Prototype& prototype = *prototypes_[instances_[g.index].prototype];
  return prototype.shape ? &*prototype.shape : nullptr;
}

const app::Placement& EmbreeScene::placementOf(std::uint32_t id) const noexcept {
  static const app::Placement identity;
  const Geometry& g = geometries_[id];
  return g.mesh ? identity : instances_[g.index].placement;
}

const TriangleMesh* EmbreeScene::meshOf(std::uint32_t id) const noexcept {
  const Geometry& g = geometries_[id];
  return g.mesh ? &meshes_[g.index] : nullptr;
}

bool EmbreeScene::worldNormals(std::uint32_t id) const noexcept {
  const Geometry& g = geometries_[id];
  return g.mesh || instances_[g.index].worldNormals;
}

revolve::Geometry EmbreeScene::exactGeometry(const Shape& shape, const Instance& instance) const {
  const revolve::Geometry::Options options{.countStats = countStats_};
  if (instance.placement.isIdentity()) return revolve::Geometry(device_.get(), shape, options);
  // The linear part as the instance's records hold it (rounded to float, as an Embree instance
  // would hold it), so that the hit's normal and error bound (instanceHit) are of the same map.
  revolve::Placement placement;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) placement.linear[r][c] = instance.linear.m[r][c];
    placement.translate[r] = (&instance.translate.x)[r];
  }
  return revolve::Geometry(device_.get(), shape, placement, options);
}

RTCScene EmbreeScene::filteredScene(RTCFilterFunctionN filter) {
  if (filteredCurrent_) return filtered_.get();
  app::Scene scene = app::newScene(device_.get());
  if (layout_.robust) rtcSetSceneFlags(scene.get(), RTC_SCENE_FLAG_ROBUST);
  for (std::uint32_t id = 0; id < geometries_.size(); ++id) {
    const Geometry& g = geometries_[id];
    if (g.mesh) {
      RTCGeometry geometry = newTriangles(device_.get(), meshes_[g.index]);
      rtcSetGeometryIntersectFilterFunction(geometry, filter);
      rtcCommitGeometry(geometry);
      rtcAttachGeometryByID(scene.get(), geometry, id);
      rtcReleaseGeometry(geometry);
      continue;
    }
    Instance& instance = instances_[g.index];
    const Prototype& prototype = *prototypes_[instance.prototype];
    if (!prototype.shape) throw std::logic_error("filteredScene: only surfaces traced exactly carry filters");
    if (!instance.filtered) {
      instance.filtered = exactGeometry(*prototype.shape, instance);
      instance.filtered->setIntersectFilter(filter);
      rtcCommitGeometry(instance.filtered->handle());
    }
    rtcAttachGeometryByID(scene.get(), instance.filtered->handle(), id);
  }
  rtcCommitScene(scene.get());
  if (rtcGetDeviceError(device_.get()) != RTC_ERROR_NONE) throw std::runtime_error("Embree failed to build the scene");
  filtered_ = std::move(scene);
  filteredCurrent_ = true;
  return filtered_.get();
}

std::uint32_t EmbreeScene::objectOf(const RTCHit& hit) const noexcept {
  const std::uint32_t id = hit.instID[0] != RTC_INVALID_GEOMETRY_ID ? hit.instID[0] : hit.geomID;
  const Geometry& g = geometries_[id];
  if (g.mesh && !meshes_[g.index].quadMaterials.empty()) return id + hit.primID / 2;  // quads follow the objects
  return id;
}

// A range-finder's hit for every beam that returns: kept to a few float operations (the normal through
// the instance's inverse transpose in float, made unit), since a scan makes millions of them.
RangeHit EmbreeScene::rangeHitOf(const RTCHit& hit, float t) const noexcept {
  const std::uint32_t id = hit.instID[0] != RTC_INVALID_GEOMETRY_ID ? hit.instID[0] : hit.geomID;
  const Geometry& g = geometries_[id];
  Vec3 n{hit.Ng_x, hit.Ng_y, hit.Ng_z};  // object space unless worldNormals (a mesh, an identity placement)
  RangeHit range;
  range.t = t;
  range.object = id;
  if (g.mesh) {
    const TriangleMesh& mesh = meshes_[g.index];
    if (!mesh.quadMaterials.empty()) range.object = id + hit.primID / 2;  // quads follow the objects
    if (!mesh.quadReflectivities.empty()) range.reflectivity = mesh.quadReflectivities[hit.primID / 2];
  } else {
    const Instance& instance = instances_[g.index];
    if (!instance.worldNormals) {
      const std::array<float, 9>& m = instance.rangeNormalMatrix;
      n = {m[0] * n.x + m[1] * n.y + m[2] * n.z, m[3] * n.x + m[4] * n.y + m[5] * n.z,
           m[6] * n.x + m[7] * n.y + m[8] * n.z};
    }
    range.reflectivity = instance.reflectivity;
  }
  range.normal = app::normalize(n);
  return range;
}

std::optional<WorldHit> EmbreeScene::hitOf(const Ray& ray, const RTCRayHit& rayHit) const noexcept {
  const std::uint32_t id = rayHit.hit.instID[0] != RTC_INVALID_GEOMETRY_ID ? rayHit.hit.instID[0] : rayHit.hit.geomID;
  const Geometry& g = geometries_[id];
  return g.mesh ? triangleHit(id, ray, rayHit) : instanceHit(instances_[g.index], ray, rayHit);
}

std::optional<WorldHit> EmbreeScene::intersect(const Ray& ray) const noexcept {
  if (!app::embreeAccepts(ray)) {
    refused_->fetch_add(1, std::memory_order_relaxed);
    return std::nullopt;
  }
  embree::RayQuery query;
  RTCRayHit rayHit = app::embreeRayHit(ray);
  const float length = unitDirections_ ? normaliseDirection(rayHit.ray) : 1.0f;
  query.intersect(top_.get(), rayHit);
  if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  rayHit.ray.tfar /= length;
  return hitOf(ray, rayHit);
}

std::optional<RangeHit> EmbreeScene::nearest(const Ray& ray) const noexcept {
  if (!app::embreeAccepts(ray)) {
    refused_->fetch_add(1, std::memory_order_relaxed);
    return std::nullopt;
  }
  embree::RayQuery query;
  RTCRayHit rayHit = app::embreeRayHit(ray);
  const float length = unitDirections_ ? normaliseDirection(rayHit.ray) : 1.0f;
  query.intersect(top_.get(), rayHit);
  if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  rayHit.ray.tfar /= length;
  return rangeHitOf(rayHit.hit, rayHit.ray.tfar);
}

bool EmbreeScene::occluded(const Ray& ray) const noexcept {
  if (!app::embreeAccepts(ray)) {
    refused_->fetch_add(1, std::memory_order_relaxed);
    return false;
  }
  embree::RayQuery query;
  RTCRay shadow = app::embreeRayHit(ray).ray;
  if (unitDirections_) normaliseDirection(shadow);
  query.occluded(top_.get(), shadow);
  return shadow.tfar == -std::numeric_limits<float>::infinity();
}

void EmbreeScene::tracePacket(std::span<const Ray> rays, RTCRayHit8& packet,
                              float (&lengths)[kPacketRays]) const noexcept {
  // Every lane starts as a ray that is not traced: empty interval, no hit. A traced lane holds
  // exactly the record the single-ray query would have been given.
  alignas(32) int valid[kPacketRays];
  const RTCRayHit idle = embree::newRayHit(0, 0, 0, 0, 0, 1, 0, -std::numeric_limits<float>::infinity());
  for (std::size_t k = 0; k < kPacketRays; ++k) {
    valid[k] = 0;
    lengths[k] = 1.0f;
    if (k < rays.size() && !app::embreeAccepts(rays[k])) refused_->fetch_add(1, std::memory_order_relaxed);
    if (k >= rays.size() || !app::embreeAccepts(rays[k])) {
      app::setPacketLane(packet, int(k), idle);
      continue;
    }
    RTCRayHit one = app::embreeRayHit(rays[k]);
    if (unitDirections_) lengths[k] = normaliseDirection(one.ray);
    app::setPacketLane(packet, int(k), one);
    valid[k] = -1;
  }
  embree::RayQuery query;
  query.intersect(valid, top_.get(), packet);
  // Lanes left out keep their empty hit: Embree writes only valid lanes.
}

void EmbreeScene::intersect(std::span<const Ray> rays, std::span<std::optional<WorldHit>> hits) const noexcept {
  alignas(32) RTCRayHit8 packet;
  float lengths[kPacketRays];
  tracePacket(rays, packet, lengths);
  for (std::size_t k = 0; k < rays.size(); ++k) {
    RTCRayHit rayHit = app::packetLane(packet, int(k));
    if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
      hits[k] = std::nullopt;
      continue;
    }
    rayHit.ray.tfar /= lengths[k];
    hits[k] = hitOf(rays[k], rayHit);
  }
}

void EmbreeScene::nearest(std::span<const Ray> rays, std::span<std::optional<RangeHit>> hits) const noexcept {
  alignas(32) RTCRayHit8 packet;
  float lengths[kPacketRays];
  tracePacket(rays, packet, lengths);
  for (std::size_t k = 0; k < rays.size(); ++k) {
    if (packet.hit.geomID[k] == RTC_INVALID_GEOMETRY_ID) {
      hits[k] = std::nullopt;
      continue;
    }
    const float t = packet.ray.tfar[k] / lengths[k];
    RTCHit hit{};
    hit.instID[0] = packet.hit.instID[0][k];
    hit.geomID = packet.hit.geomID[k];
    hit.primID = packet.hit.primID[k];
    hit.Ng_x = packet.hit.Ng_x[k], hit.Ng_y = packet.hit.Ng_y[k], hit.Ng_z = packet.hit.Ng_z[k];
    hits[k] = rangeHitOf(hit, t);
  }
}

std::optional<WorldHit> EmbreeScene::instanceHit(const Instance& instance, const Ray& ray,
                                                 const RTCRayHit& rayHit) const noexcept {
  const Prototype& prototype = *prototypes_[instance.prototype];
  WorldHit hit;
  hit.t = rayHit.ray.tfar;
  hit.ray = ray;
  hit.material = instance.material;
  hit.object = instance.id;
  Vec3 objectNormal, shadingNormal;
  if (prototype.cone() != nullptr) {
    // Embree's cone curve: its Ng turned to revolve's side, the profile segment and u, v recovered
    // from the point. Its single-precision hit comes with no error bound: the point's own distance
    // from its cone (in double, object space) stands in for one, with the rounding of o + t d.
    const ConeCurveGeometry& cone = *prototype.cone();
    const Vec3 ng{rayHit.hit.Ng_x, rayHit.hit.Ng_y, rayHit.hit.Ng_z};
    const std::uint32_t segment = cone.profileSegment(rayHit.hit.primID, rayHit.hit.u, ng);
    hit.point = ray.origin + hit.t * ray.direction;
    const Vec3 offset = hit.point - instance.translate;  // world to object: L^-1 (p - T), L^-1 = normalMatrix^T
    const app::Matrix3d& n = instance.normalMatrix;
    const Vec3 local{float(n.m[0][0] * offset.x + n.m[1][0] * offset.y + n.m[2][0] * offset.z),
                     float(n.m[0][1] * offset.x + n.m[1][1] * offset.y + n.m[2][1] * offset.z),
                     float(n.m[0][2] * offset.x + n.m[1][2] * offset.y + n.m[2][2] * offset.z)};
    objectNormal = cone.normalSign(rayHit.hit.primID) * ng;
    const auto [u, v] = surfaceParameters(prototype.polyline(), segment, local);
    shadingNormal = prototype.normals->normal(segment, u, v);
    const float residual =
        float(instance.linear.infinityNorm() * distanceToSegment(prototype.polyline(), segment, local));
    const float rounding =
        float(gamma(3)) * app::maxComponent(app::absolute(ray.origin) + app::absolute(hit.t * ray.direction));
    hit.pointError = {residual + rounding, residual + rounding, residual + rounding};
  } else if (!prototype.approximation) {
    // Exact surface: Ng, u, v and primID in revolve's conventions (object space).
    hit.exactSurface = true;
    hit.point = ray.origin + hit.t * ray.direction;
    objectNormal = {rayHit.hit.Ng_x, rayHit.hit.Ng_y, rayHit.hit.Ng_z};
    // A curve's geometric normal is smooth already; a polyline's is interpolated between vertices.
    shadingNormal = prototype.shape->spline() != nullptr ? objectNormal
                    : prototype.normals ? prototype.normals->normal(rayHit.hit.primID, rayHit.hit.u, rayHit.hit.v)
                                        : objectNormal;
    const Vec3 magnitude =
        app::absolute(ray.origin) + app::absolute(instance.translate) + app::absolute(hit.t * ray.direction);
    hit.transformError = instance.transformErrorFactor * app::maxComponent(magnitude);
  } else {
    // Mesh: the point from the triangle's barycentrics (pbrt-v4: within gamma(7) sum |b_i p_i|),
    // then revolve's segment, u and v recovered from it so that shading matches the exact surface.
    const Prototype::Approximation& mesh = *prototype.approximation;
    const std::uint32_t* index = mesh.meshIndices + 3 * rayHit.hit.primID;
    const auto vertex = [&](int k) {
      const float* v = mesh.meshVertices + 3 * index[k];
      return Vec3{v[0], v[1], v[2]};
    };
    const Vec3 p0 = vertex(0), p1 = vertex(1), p2 = vertex(2);
    const float b1 = rayHit.hit.u, b2 = rayHit.hit.v, b0 = 1 - b1 - b2;
    const Vec3 local = b0 * p0 + b1 * p1 + b2 * p2;
    const Vec3 localError =
        float(gamma(7)) * (app::absolute(b0 * p0) + app::absolute(b1 * p1) + app::absolute(b2 * p2));
    objectNormal = app::cross(p1 - p0, p2 - p0);  // outwards for a profile listed bottom to top, as Ng
    const std::uint32_t segment = rayHit.hit.primID / (2 * mesh.slices);
    const auto [u, v] = surfaceParameters(prototype.polyline(), segment, local);
    shadingNormal = prototype.normals->normal(segment, u, v);
    // World point L p + T: its own rounding (gamma(3) (|L| |p| + |T|)) plus the object error through |L|.
    hit.point = instance.linear.apply(local) + instance.translate;
    hit.pointError =
        instance.linear.applyAbsolute(localError) +
        float(gamma(3)) * (instance.linear.applyAbsolute(app::absolute(local)) + app::absolute(instance.translate));
  }
  hit.geometricNormal = app::normalize(instance.normalMatrix.apply(objectNormal));
  hit.shadingNormal = app::normalize(instance.normalMatrix.apply(shadingNormal));
  return hit;
}

std::optional<WorldHit> EmbreeScene::triangleHit(std::uint32_t id, const Ray& ray,
                                                 const RTCRayHit& rayHit) const noexcept {
  const TriangleMesh& mesh = meshes_[geometries_[id].index];
  const std::uint32_t* index = mesh.triangles.data() + 3 * std::size_t(rayHit.hit.primID);
  const auto vertex = [&](int k) {
    const float* v = mesh.vertices.data() + 3 * std::size_t(index[k]);
    return Vec3{v[0], v[1], v[2]};
  };
  const Vec3 p0 = vertex(0), p1 = vertex(1), p2 = vertex(2);
  const float b1 = rayHit.hit.u, b2 = rayHit.hit.v, b0 = 1 - b1 - b2;
  WorldHit hit;
  hit.t = rayHit.ray.tfar;
  hit.ray = ray;
  hit.material = mesh.quadMaterials.empty() ? 0 : mesh.quadMaterials[rayHit.hit.primID / 2];
  hit.object = objectOf(rayHit.hit);
  hit.point = b0 * p0 + b1 * p1 + b2 * p2;
  hit.pointError = float(gamma(7)) * (app::absolute(b0 * p0) + app::absolute(b1 * p1) + app::absolute(b2 * p2));
  hit.geometricNormal = app::normalize(app::cross(p1 - p0, p2 - p0));
  hit.shadingNormal = hit.geometricNormal;
  return hit;
}

Vec3 EmbreeScene::spawn(const WorldHit& hit, Vec3 direction) const noexcept {
  if (hit.exactSurface) {
    const Vec3 p = offsetRayOrigin(hit.ray, hit.t, hit.geometricNormal, direction);
    return pushAlongNormal(p, hit.geometricNormal, hit.transformError, direction);
  }
  // The error box's extent along the normal: sum |n_i| e_i.
  const float distance = app::dot(app::absolute(hit.geometricNormal), hit.pointError);
  return pushAlongNormal(hit.point, hit.geometricNormal, distance, direction);
}

std::size_t EmbreeScene::meshBytes() const noexcept {
  std::size_t bytes = 0;
  for (const TriangleMesh& mesh : meshes_)
    bytes += mesh.vertices.capacity() * sizeof(float) + mesh.triangles.capacity() * sizeof(std::uint32_t);
  return bytes;
}

Stats EmbreeScene::stats() const noexcept {
  Stats total;
  for (const Instance& instance : instances_) {
    if (instance.exact) total += instance.exact->stats();
  }
  return total;
}

std::size_t EmbreeScene::treeNodeCount() const noexcept {
  std::size_t nodes = 0;
  for (const Instance& instance : instances_) {
    const Prototype& prototype = *prototypes_[instance.prototype];
    if (prototype.shape) nodes += prototype.shape->treeNodeCount();
  }
  return nodes;
}

std::size_t EmbreeScene::revolveBytes() const noexcept {
  std::size_t bytes = 0;
  for (const auto& prototype : prototypes_) {
    if (prototype->normals) bytes += prototype->normals->memoryBytes();
    if (prototype->shape) bytes += prototype->shape->memoryBytes();
  }
  return bytes;
}

std::size_t EmbreeScene::recordBytes() const noexcept {
  std::size_t geometryBytes = 0;  // what revolve keeps beside each exact surface's Embree geometry
  for (const Instance& instance : instances_) {
    if (instance.exact) geometryBytes += instance.exact->memoryBytes();
    if (instance.filtered) geometryBytes += instance.filtered->memoryBytes();
  }
  std::size_t prototypeBytes = prototypes_.capacity() * sizeof(std::unique_ptr<Prototype>);
  for (const auto& prototype : prototypes_) {
    prototypeBytes += sizeof(Prototype) + (prototype->normals ? sizeof(ShadingNormals) : 0);
    // A mesh's or cone curve's record and polyline (its triangles and cones are Embree's).
    if (const Prototype::Approximation* approximation = prototype->approximation.get()) {
      const Profile& polyline = approximation->profile;
      prototypeBytes += sizeof(Prototype::Approximation) + polyline.points().size() * sizeof(Point2) +
                        polyline.arcLength().size() * sizeof(double);
    }
  }
  return instances_.capacity() * sizeof(Instance) + geometries_.capacity() * sizeof(Geometry) + prototypeBytes +
         geometryBytes;
}

std::int64_t EmbreeScene::embreeBytes() const noexcept { return memory_->current.load(); }
std::int64_t EmbreeScene::embreePeakBytes() const noexcept { return memory_->peak.load(); }

}  // namespace revolve::scene
