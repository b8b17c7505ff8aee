#include "scene/embree_scene.h"

#include "embree/embree_rays.h"
#include "embree/memory_check.h"
#include "geometry/ray_limits.h"
#include "geometry/vector_math.h"
#include "geometry/transform.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace revolve::scene {

using app::operator+;  // common/vector_math.h
using app::operator-;
using app::operator*;

namespace {

constexpr double kUnitRoundoff = 0x1p-24;  // float's u
// pbrt-v4's gamma(n) = n u / (1 - n u): the relative error bound of n float operations.
constexpr double gamma(int n) { return n * kUnitRoundoff / (1 - n * kUnitRoundoff); }

Vec3 toVec3(const io::Vec3d& v) { return {float(v[0]), float(v[1]), float(v[2])}; }

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
  if (source.curve && !source.profile.curveParameters().empty()) return ShadingNormals(source.profile, *source.curve);
  return ShadingNormals(source.profile, source.creaseDegrees);
}

}  // namespace

struct EmbreeScene::Prototype {
  Profile profile;
  ShadingNormals normals;
  std::optional<Shape> shape;
  std::optional<Geometry> geometry;
  std::optional<ConeCurveGeometry> cone;
  RTCGeometry mesh = nullptr;  // retained while the prototype lives
  const float* meshVertices = nullptr;
  const std::uint32_t* meshIndices = nullptr;
  std::uint32_t slices = 0;
  app::Scene scene;

  Prototype(const io::SceneProfile& source, RTCDevice device, const BuildSettings& settings)
      : profile(source.profile), normals(shadingNormalsOf(source)), scene(app::newScene(device)) {
    if (settings.mesh) {
      slices = settings.slices;
      mesh = newTessellatedGeometry(device, profile, slices);
      meshVertices = static_cast<const float*>(rtcGetGeometryBufferData(mesh, RTC_BUFFER_TYPE_VERTEX, 0));
      meshIndices = static_cast<const std::uint32_t*>(rtcGetGeometryBufferData(mesh, RTC_BUFFER_TYPE_INDEX, 0));
      if (meshVertices == nullptr || meshIndices == nullptr) throw std::runtime_error("Embree gave no mesh buffers");
      rtcAttachGeometry(scene.get(), mesh);
    } else if (settings.embreeCone) {
      cone.emplace(device, profile);
      rtcAttachGeometry(scene.get(), cone->handle());
    } else if (source.spline) {
      shape.emplace(*source.spline, settings.options);  // the curve itself, its normals smooth already
      geometry.emplace(device, *shape, Geometry::Options{.countStats = settings.countStats});
      rtcAttachGeometry(scene.get(), geometry->handle());
    } else {
      shape.emplace(profile, settings.options);
      geometry.emplace(device, *shape, Geometry::Options{.countStats = settings.countStats});
      rtcAttachGeometry(scene.get(), geometry->handle());
    }
    rtcCommitScene(scene.get());
  }
  ~Prototype() {
    if (mesh != nullptr) rtcReleaseGeometry(mesh);
  }
  Prototype(const Prototype&) = delete;
  Prototype& operator=(const Prototype&) = delete;
};

struct EmbreeScene::Instance {
  std::uint32_t prototype = 0, material = 0;
  Matrix3d linear{}, normalMatrix{};  // object to world, and its inverse transpose for normals
  Vec3 translate{};
  // Embree maps the world ray into object space in float: o' = L^-1 (o - T), d' = L^-1 d, each
  // component within gamma(3) of |L^-1| (|o| + |T|) and |L^-1| |d|. Mapped back through L, the
  // exact hit of that ray lies within gamma(3) |L| |L^-1| (|o| + |T| + |t d|) of the world ray's
  // (infinity norms); this is that factor, gamma(3) |L| |L^-1|, with room (gamma(4)).
  float transformErrorFactor = 0;
};

EmbreeScene::EmbreeScene(const io::SceneDescription& description, const BuildSettings& settings)
    : memory_(std::make_unique<MemoryCounter>()), device_(app::newDevice()) {
  const auto start = std::chrono::steady_clock::now();
  rtcSetDeviceMemoryMonitorFunction(
      device_.get(),
      [](void* user, ssize_t bytes, bool) {
        auto* counter = static_cast<MemoryCounter*>(user);
        const std::int64_t now = counter->current.fetch_add(bytes) + bytes;
        std::int64_t peak = counter->peak.load();
        while (now > peak && !counter->peak.compare_exchange_weak(peak, now)) {}
        return true;
      },
      memory_.get());

  if (settings.embreeCone) {
    for (std::size_t i = 0; i < description.objects.size(); ++i) {
      const io::SceneObject& object = description.objects[i];
      const io::SceneProfile& profile = description.profiles[object.profile];
      // A profile made from a curve is traced as its polyline: its points are that polyline's, not
      // the scene's, and the message says so.
      const bool fromCurve = profile.spline || profile.tolerance > 0;
      std::string which = description.file + ": objects[" + std::to_string(i) + "]" +
                          (object.name.empty() ? "" : " \"" + object.name + "\"") + " (profiles." + profile.name;
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
              coneCurveLimitation(profile.profile, fromCurve ? "polyline point" : "profile point")) {
        throw std::runtime_error(which + " cannot be traced as Embree's linear cone curve: " + *limitation);
      }
      const io::Vec3d& scale = object.transform.scale;
      if (scale[0] != 1 || scale[1] != 1 || scale[2] != 1) {
        char text[96];
        std::snprintf(text, sizeof text, "%.9g, %.9g, %.9g", scale[0], scale[1], scale[2]);
        throw std::runtime_error(which + " is scaled by (" + text +
                                 "): Embree's linear cone curve kernel assumes unit ray directions, and an instance's "
                                 "scale changes their length in object space; scale its profile's points instead");
      }
    }
  }
  unitDirections_ = settings.embreeCone;

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
      triangles += 2.0 * double(description.profiles[profile].profile.segmentCount()) * settings.slices;
    app::requireMemory(triangles * app::kMeshBytesPerTriangle,
                       "--geometry mesh with " + std::to_string(settings.slices) + " slices (" +
                           std::to_string(std::uint64_t(triangles)) + " triangles)");
  }
  prototypes_.resize(used.size());
  tbb::parallel_for(std::size_t{0}, used.size(), [&](std::size_t i) {
    prototypes_[i] = std::make_unique<Prototype>(description.profiles[used[i]], device_.get(), settings);
  });

  top_ = app::newScene(device_.get());
  instances_.reserve(description.objects.size());
  for (std::size_t i = 0; i < description.objects.size(); ++i) {
    const io::SceneObject& object = description.objects[i];
    Instance instance;
    instance.prototype = std::uint32_t(prototypeOf[object.profile]);
    instance.material = std::uint32_t(object.material);
    instance.linear = roundedToFloat(linearPart(object.transform));  // the floats Embree will use
    const Matrix3d inv = inverse(instance.linear);
    // What the reader's limits on scales guarantee (common/ray_limits.h), checked here too for
    // descriptions made in code: Embree's object-space rays stay within its range.
    if (!(inv.infinityNorm() * (app::kMaxRayOrigin + app::kMaxWorldCoordinate) <= 0.5 * double(app::kEmbreeLargest)) ||
        !(instance.linear.infinityNorm() <= 3 * app::kMaxScale) ||
        !(instance.linear.infinityNorm() * inv.infinityNorm() <= 3 * app::kMaxScaleRatio * (1 + 0x1p-20))) {
      throw std::runtime_error(
          description.file + ": objects[" + std::to_string(i) +
          "]: its transform would carry rays beyond Embree's range; scale factors lie in [2^-16, 2^40], "
          "within a factor 2^16 of each other");
    }
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) instance.normalMatrix.m[r][c] = inv.m[c][r];
    }
    instance.translate = toVec3(object.transform.translate);
    instance.transformErrorFactor = float(gamma(4) * instance.linear.infinityNorm() * inv.infinityNorm());
    float columns[12];
    for (int c = 0; c < 3; ++c) {
      for (int r = 0; r < 3; ++r) columns[3 * c + r] = float(instance.linear.m[r][c]);
    }
    columns[9] = instance.translate.x;
    columns[10] = instance.translate.y;
    columns[11] = instance.translate.z;
    RTCGeometry geometry = rtcNewGeometry(device_.get(), RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(geometry, prototypes_[instance.prototype]->scene.get());
    rtcSetGeometryTransform(geometry, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, columns);
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(top_.get(), geometry, unsigned(i));
    rtcReleaseGeometry(geometry);
    instances_.push_back(instance);
  }

  if (!description.quads.empty()) {
    RTCGeometry triangles = rtcNewGeometry(device_.get(), RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        triangles, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 4 * description.quads.size()));
    auto* indices =
        static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(triangles, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                            3 * sizeof(std::uint32_t), 2 * description.quads.size()));
    for (std::size_t q = 0; q < description.quads.size(); ++q) {
      const io::SceneQuad& quad = description.quads[q];
      for (int c = 0; c < 4; ++c) {
        const Vec3 v = toVec3(quad.corners[c]);
        quadVertices_.push_back(v);
        vertices[3 * (4 * q + c) + 0] = v.x;
        vertices[3 * (4 * q + c) + 1] = v.y;
        vertices[3 * (4 * q + c) + 2] = v.z;
      }
      const std::uint32_t base = std::uint32_t(4 * q);
      const std::uint32_t triangle[6] = {base, base + 1, base + 2, base, base + 2, base + 3};
      std::copy(triangle, triangle + 6, indices + 6 * q);
      quadMaterials_.push_back(std::uint32_t(quad.material));
    }
    rtcCommitGeometry(triangles);
    rtcAttachGeometryByID(top_.get(), triangles, unsigned(description.objects.size()));
    rtcReleaseGeometry(triangles);
  }
  rtcCommitScene(top_.get());
  if (rtcGetDeviceError(device_.get()) != RTC_ERROR_NONE)
    throw std::runtime_error(description.file + ": Embree failed to build the scene");
  buildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

EmbreeScene::~EmbreeScene() {
  top_.reset();
  prototypes_.clear();
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
  return rayHit.hit.instID[0] != RTC_INVALID_GEOMETRY_ID ? instanceHit(ray, rayHit) : quadHit(ray, rayHit);
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
  const bool instance = rayHit.hit.instID[0] != RTC_INVALID_GEOMETRY_ID;
  return RangeHit{rayHit.ray.tfar,
                  instance ? rayHit.hit.instID[0] : std::uint32_t(instances_.size() + rayHit.hit.primID / 2)};
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
    hits[k] = rayHit.hit.instID[0] != RTC_INVALID_GEOMETRY_ID ? instanceHit(rays[k], rayHit) : quadHit(rays[k], rayHit);
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
    const std::uint32_t instance = packet.hit.instID[0][k];
    hits[k] =
        RangeHit{t, instance != RTC_INVALID_GEOMETRY_ID ? instance
                                                        : std::uint32_t(instances_.size() + packet.hit.primID[k] / 2)};
  }
}

std::optional<WorldHit> EmbreeScene::instanceHit(const Ray& ray, const RTCRayHit& rayHit) const noexcept {
  const Instance& instance = instances_[rayHit.hit.instID[0]];
  const Prototype& prototype = *prototypes_[instance.prototype];
  WorldHit hit;
  hit.t = rayHit.ray.tfar;
  hit.ray = ray;
  hit.material = instance.material;
  hit.object = rayHit.hit.instID[0];
  Vec3 objectNormal, shadingNormal;
  if (prototype.cone) {
    // Embree's cone curve: its Ng turned to revolve's side, the profile segment and u, v recovered
    // from the point. Its single-precision hit comes with no error bound: the point's own distance
    // from its cone (in double, object space) stands in for one, with the rounding of o + t d.
    const ConeCurveGeometry& cone = *prototype.cone;
    const Vec3 ng{rayHit.hit.Ng_x, rayHit.hit.Ng_y, rayHit.hit.Ng_z};
    const std::uint32_t segment = cone.profileSegment(rayHit.hit.primID, rayHit.hit.u, ng);
    hit.point = ray.origin + hit.t * ray.direction;
    const Vec3 offset = hit.point - instance.translate;  // world to object: L^-1 (p - T), L^-1 = normalMatrix^T
    const Matrix3d& n = instance.normalMatrix;
    const Vec3 local{float(n.m[0][0] * offset.x + n.m[1][0] * offset.y + n.m[2][0] * offset.z),
                     float(n.m[0][1] * offset.x + n.m[1][1] * offset.y + n.m[2][1] * offset.z),
                     float(n.m[0][2] * offset.x + n.m[1][2] * offset.y + n.m[2][2] * offset.z)};
    objectNormal = cone.normalSign(rayHit.hit.primID) * ng;
    const auto [u, v] = surfaceParameters(prototype.profile, segment, local);
    shadingNormal = prototype.normals.normal(segment, u, v);
    const float residual = float(instance.linear.infinityNorm() * distanceToSegment(prototype.profile, segment, local));
    const float rounding =
        float(gamma(3)) * app::maxComponent(app::absolute(ray.origin) + app::absolute(hit.t * ray.direction));
    hit.pointError = {residual + rounding, residual + rounding, residual + rounding};
  } else if (prototype.mesh == nullptr) {
    // Exact surface: Ng, u, v and primID in revolve's conventions (object space).
    hit.exactSurface = true;
    hit.point = ray.origin + hit.t * ray.direction;
    objectNormal = {rayHit.hit.Ng_x, rayHit.hit.Ng_y, rayHit.hit.Ng_z};
    // A curve's geometric normal is smooth already; a polyline's is interpolated between vertices.
    shadingNormal = prototype.shape->spline() != nullptr
                        ? objectNormal
                        : prototype.normals.normal(rayHit.hit.primID, rayHit.hit.u, rayHit.hit.v);
    const Vec3 magnitude =
        app::absolute(ray.origin) + app::absolute(instance.translate) + app::absolute(hit.t * ray.direction);
    hit.transformError = instance.transformErrorFactor * app::maxComponent(magnitude);
  } else {
    // Mesh: the point from the triangle's barycentrics (pbrt-v4: within gamma(7) sum |b_i p_i|),
    // then revolve's segment, u and v recovered from it so that shading matches the exact surface.
    const std::uint32_t* index = prototype.meshIndices + 3 * rayHit.hit.primID;
    const auto vertex = [&](int k) {
      const float* v = prototype.meshVertices + 3 * index[k];
      return Vec3{v[0], v[1], v[2]};
    };
    const Vec3 p0 = vertex(0), p1 = vertex(1), p2 = vertex(2);
    const float b1 = rayHit.hit.u, b2 = rayHit.hit.v, b0 = 1 - b1 - b2;
    const Vec3 local = b0 * p0 + b1 * p1 + b2 * p2;
    const Vec3 localError =
        float(gamma(7)) * (app::absolute(b0 * p0) + app::absolute(b1 * p1) + app::absolute(b2 * p2));
    objectNormal = app::cross(p1 - p0, p2 - p0);  // outwards for a profile listed bottom to top, as Ng
    const std::uint32_t segment = rayHit.hit.primID / (2 * prototype.slices);
    const auto [u, v] = surfaceParameters(prototype.profile, segment, local);
    shadingNormal = prototype.normals.normal(segment, u, v);
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

std::optional<WorldHit> EmbreeScene::quadHit(const Ray& ray, const RTCRayHit& rayHit) const noexcept {
  const std::uint32_t quad = rayHit.hit.primID / 2;
  const Vec3* corner = quadVertices_.data() + 4 * quad;
  const bool second = rayHit.hit.primID % 2 == 1;
  const Vec3 p0 = corner[0], p1 = second ? corner[2] : corner[1], p2 = second ? corner[3] : corner[2];
  const float b1 = rayHit.hit.u, b2 = rayHit.hit.v, b0 = 1 - b1 - b2;
  WorldHit hit;
  hit.t = rayHit.ray.tfar;
  hit.ray = ray;
  hit.material = quadMaterials_[quad];
  hit.object = std::uint32_t(instances_.size() + quad);
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

Stats EmbreeScene::stats() const noexcept {
  Stats total;
  for (const auto& prototype : prototypes_) {
    if (prototype->geometry) total += prototype->geometry->stats();
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
    bytes += prototype->normals.memoryBytes();
    if (prototype->shape) bytes += prototype->shape->memoryBytes();
  }
  return bytes;
}

std::int64_t EmbreeScene::embreeBytes() const noexcept { return memory_->current.load(); }
std::int64_t EmbreeScene::embreePeakBytes() const noexcept { return memory_->peak.load(); }

}  // namespace revolve::scene
