#include "raycasting_scene.h"

#include "query_limits.h"
#include "solid_inside.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>
#include <numbers>
#include <stdexcept>

namespace revolve::python {

struct RaycastingScene::Revolution {
  Shape shape;
  Placement placement;
  // The shape alone, instanced under the geometry's id; none when it stays where it is (the
  // identity), attached to the top scene itself: an instance costs each ray a second traversal
  // and two transforms.
  app::Scene prototype;
  std::optional<Geometry> geometry;
  // The same shape with a filter counting every crossing (count_intersections), built on first use,
  // attached the same way.
  app::Scene countingPrototype;
  std::optional<Geometry> countingGeometry;
};

struct RaycastingScene::Mesh {
  std::vector<float> vertices;  // 3 a vertex, and one more float: Embree reads a vertex as 16 bytes
  std::vector<std::uint32_t> triangles;
  std::size_t vertexCount = 0, triangleCount = 0;
};

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// count_intersections: the counter of the ray the calling thread traces (a filter function runs on
// the thread that called rtcIntersect1), and the crossing it saw last.
struct CrossingCount {
  std::int32_t count = 0;
  unsigned geometry = RTC_INVALID_GEOMETRY_ID;
  float t = 0;
};
thread_local CrossingCount* crossings = nullptr;

// Counts the candidate and rejects it, so that Embree goes on to the next one. A hit on the edge
// shared by two triangles of one mesh is offered twice at the same t: counted once, as Open3D's
// RaycastingScene counts. (Open3D also skips a repeated primitive at another t, which cannot
// happen for a triangle; a surface of revolution's segment, a cone, is crossed twice by many rays.)
void countCrossing(const RTCFilterFunctionNArguments* args) {
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    args->valid[i] = 0;
    if (crossings == nullptr) continue;
    const unsigned instance = RTCHitN_instID(args->hit, args->N, i, 0);
    const unsigned geometry = instance != RTC_INVALID_GEOMETRY_ID ? instance : RTCHitN_geomID(args->hit, args->N, i);
    const float t = RTCRayN_tfar(args->ray, args->N, i);
    CrossingCount& c = *crossings;
    if (geometry != c.geometry || t != c.t) {
      ++c.count;
      c.geometry = geometry, c.t = t;
    }
  }
}

Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3d minus(const Vec3d& a, const Vec3d& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

// The closest point so far of a point query, in double.
struct Candidate {
  double distance = std::numeric_limits<double>::infinity();
  Vec3d point{}, normal{};
  double u = 0, v = 0;
  std::uint32_t geometry = RTC_INVALID_GEOMETRY_ID, primitive = RTC_INVALID_GEOMETRY_ID;
};

struct PointQuery {
  const std::vector<std::unique_ptr<RaycastingScene::Revolution>>* revolutions;
  const std::vector<std::unique_ptr<RaycastingScene::Mesh>>* meshes;
  Vec3d query{};
  Candidate best;
};

// The closest point of triangle (a, b, c) to p by its Voronoi regions (Ericson, Real-Time Collision
// Detection, 2005, 5.1.5), as barycentrics (u, v) of b and c, in double.
std::pair<double, double> closestOnTriangle(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  const Vec3d ab = minus(b, a), ac = minus(c, a), ap = minus(p, a);
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return {0, 0};
  const Vec3d bp = minus(p, b);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return {1, 0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return {d1 / (d1 - d3), 0};
  const Vec3d cp = minus(p, c);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return {0, 1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return {0, d2 / (d2 - d6)};
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {1 - w, w};
  }
  const double denominator = 1 / (va + vb + vc);
  return {vb * denominator, vc * denominator};
}

void offerTriangle(PointQuery& q, const RaycastingScene::Mesh& mesh, unsigned id, unsigned primitive) {
  const auto vertex = [&](int k) {
    const float* v = mesh.vertices.data() + 3 * std::size_t(mesh.triangles[3 * std::size_t(primitive) + k]);
    return Vec3d{v[0], v[1], v[2]};
  };
  const Vec3d a = vertex(0), b = vertex(1), c = vertex(2);
  const auto [u, v] = closestOnTriangle(q.query, a, b, c);
  const Vec3d p{a[0] + u * (b[0] - a[0]) + v * (c[0] - a[0]), a[1] + u * (b[1] - a[1]) + v * (c[1] - a[1]),
                a[2] + u * (b[2] - a[2]) + v * (c[2] - a[2])};
  const Vec3d d = minus(p, q.query);
  const double distance = std::sqrt(dot(d, d));
  if (!(distance < q.best.distance)) return;
  // Embree's geometric normal of a triangle, (b - a) x (c - a), made unit length.
  const Vec3d n = cross(minus(b, a), minus(c, a));
  const double length = std::sqrt(dot(n, n));
  q.best = {distance, p, {n[0] / length, n[1] / length, n[2] / length}, u, v, id, primitive};
}

void offerRevolution(PointQuery& q, const RaycastingScene::Revolution& g, unsigned id) {
  const Vec3d local = g.placement.toObject(q.query);
  const double rho = std::hypot(local[0], local[1]);
  const MeridianPoint m = closestMeridianPoint(g.shape, {rho, local[2]});
  const double distance = m.distance * g.placement.similarity;
  if (!(distance < q.best.distance)) return;
  // The meridian half-plane of the query (any, on the axis).
  const double cx = rho > 0 ? local[0] / rho : 1, cy = rho > 0 ? local[1] / rho : 0;
  const std::span<const Point2> points = g.shape.profile().points();
  const Point2 a = points[m.segment], b = points[m.segment + 1];
  const double er = b.r - a.r, ez = b.z - a.z, chord = std::hypot(er, ez);
  // The normal: along the way to the query when it lies off the surface (exact wherever the surface
  // is smooth; at a vertex, the direction from the vertex), turned to the right of travel (revolve's
  // side, as a hit's normal); on the surface, the segment's (for a spline, its part's chord's).
  double nr = ez / chord, nz = -er / chord;
  if (m.distance > 0) {
    double wr = (rho - m.point.r) / m.distance, wz = (local[2] - m.point.z) / m.distance;
    if (wr * nr + wz * nz < 0) wr = -wr, wz = -wz;
    nr = wr, nz = wz;
  }
  const double along = std::clamp(((m.point.r - a.r) * er + (m.point.z - a.z) * ez) / (chord * chord), 0.0, 1.0);
  const std::span<const double> arc = g.shape.profile().arcLength();
  const double turns = std::atan2(local[1], local[0]) * (0.5 / std::numbers::pi);
  q.best.distance = distance;
  q.best.point = g.placement.toWorld({m.point.r * cx, m.point.r * cy, m.point.z});
  q.best.normal = g.placement.normalToWorld({nr * cx, nr * cy, nz});
  q.best.u = turns < 0 ? turns + 1 : turns;
  q.best.v = (arc[m.segment] + along * (arc[m.segment + 1] - arc[m.segment])) / arc.back();
  q.best.geometry = id;
  q.best.primitive = m.segment;
}

bool pointQueryCallback(RTCPointQueryFunctionArguments* args) {
  auto& q = *static_cast<PointQuery*>(args->userPtr);
  const double before = q.best.distance;
  const unsigned id = args->context->instStackSize > 0 ? args->context->instID[0] : args->geomID;
  if (const RaycastingScene::Revolution* revolution = (*q.revolutions)[id].get()) {
    offerRevolution(q, *revolution, id);
  } else {
    offerTriangle(q, *(*q.meshes)[id], id, args->primID);
  }
  if (!(q.best.distance < before)) return false;
  // The radius shrinks to the best distance, rounded up so that it never excludes the best.
  args->query->radius = std::nextafter(float(q.best.distance), kInfinity);
  return true;
}

bool isIdentity(const Placement& p) {
  const Matrix3d identity{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  return p.linear == identity && p.translate == Vec3d{0, 0, 0};
}

// Attaches `geometry` to `scene` under `id`: itself, or through an instance of `prototype` (made
// here) under a placement other than the identity.
void attach(RTCDevice device, RTCScene scene, const Geometry& geometry, app::Scene& prototype,
            const Placement& placement, unsigned id) {
  if (isIdentity(placement)) {
    rtcAttachGeometryByID(scene, geometry.handle(), id);
    return;
  }
  prototype = app::newScene(device);
  rtcAttachGeometry(prototype.get(), geometry.handle());
  rtcCommitScene(prototype.get());
  RTCGeometry instance = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(instance, prototype.get());
  const std::array<float, 12> columns = placement.embreeColumns();
  rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, columns.data());
  rtcCommitGeometry(instance);
  rtcAttachGeometryByID(scene, instance, id);
  rtcReleaseGeometry(instance);
}

void recordMinimum(std::atomic<std::size_t>& first, std::size_t index) {
  std::size_t seen = first.load(std::memory_order_relaxed);
  while (index < seen && !first.compare_exchange_weak(seen, index, std::memory_order_relaxed)) {}
}

}  // namespace

RaycastingScene::RaycastingScene() : device_(app::newDevice()), top_(app::newScene(device_.get())) {
  rtcSetDeviceMemoryMonitorFunction(
      device_.get(),
      [](void* user, ssize_t bytes, bool) {
        static_cast<std::atomic<std::int64_t>*>(user)->fetch_add(bytes, std::memory_order_relaxed);
        return true;
      },
      embreeBytes_.get());
  // Watertight triangles, as Open3D's RaycastingScene asks of Embree (a ray through a mesh's edge
  // does not slip between its triangles).
  rtcSetSceneFlags(top_.get(), RTC_SCENE_FLAG_ROBUST);
}

RaycastingScene::~RaycastingScene() {
  top_.reset();
  counting_.reset();
  revolutions_.clear();
}

std::size_t RaycastingScene::memoryBytes() const {
  std::shared_lock lock(mutex_);
  std::size_t bytes = std::size_t(std::max<std::int64_t>(0, embreeBytes_->load()));
  for (const auto& g : revolutions_) bytes += g ? g->shape.memoryBytes() : 0;
  for (const auto& m : meshes_)
    bytes += m ? m->vertices.capacity() * sizeof(float) + m->triangles.capacity() * sizeof(std::uint32_t) : 0;
  return bytes;
}

std::size_t RaycastingScene::geometryCount() const {
  std::shared_lock lock(mutex_);
  return revolutions_.size();
}

std::uint32_t RaycastingScene::addRevolution(Shape shape, const Placement& placement) {
  std::unique_lock lock(mutex_);
  if (revolutions_.size() >= kInvalidId) throw std::length_error("a scene holds at most 2^32 - 1 geometries");
  const auto id = std::uint32_t(revolutions_.size());
  auto g = std::make_unique<Revolution>(
      Revolution{std::move(shape), placement, nullptr, std::nullopt, nullptr, std::nullopt});
  g->geometry.emplace(device_.get(), g->shape);
  attach(device_.get(), top_.get(), *g->geometry, g->prototype, g->placement, id);
  revolutions_.push_back(std::move(g));
  meshes_.push_back(nullptr);
  committed_ = false;
  counting_.reset();
  countingBuilt_ = false;
  return id;
}

std::uint32_t RaycastingScene::addTriangles(std::span<const float> vertices, std::span<const std::uint32_t> triangles) {
  std::unique_lock lock(mutex_);
  if (revolutions_.size() >= kInvalidId) throw std::length_error("a scene holds at most 2^32 - 1 geometries");
  const auto id = std::uint32_t(revolutions_.size());
  auto mesh = std::make_unique<Mesh>();
  mesh->vertices.assign(vertices.begin(), vertices.end());
  mesh->vertices.push_back(0);
  mesh->triangles.assign(triangles.begin(), triangles.end());
  mesh->vertexCount = vertices.size() / 3;
  mesh->triangleCount = triangles.size() / 3;
  RTCGeometry geometry = rtcNewGeometry(device_.get(), RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, mesh->vertices.data(), 0,
                             3 * sizeof(float), mesh->vertexCount);
  rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh->triangles.data(), 0,
                             3 * sizeof(std::uint32_t), mesh->triangleCount);
  rtcCommitGeometry(geometry);
  rtcAttachGeometryByID(top_.get(), geometry, id);
  rtcReleaseGeometry(geometry);
  revolutions_.push_back(nullptr);
  meshes_.push_back(std::move(mesh));
  committed_ = false;
  counting_.reset();
  countingBuilt_ = false;
  return id;
}

void RaycastingScene::commitIfChanged() {
  {
    std::shared_lock lock(mutex_);
    if (committed_) return;
  }
  std::unique_lock lock(mutex_);
  if (committed_) return;
  rtcCommitScene(top_.get());
  if (rtcGetDeviceError(device_.get()) != RTC_ERROR_NONE) throw std::runtime_error("Embree failed to build the scene");
  committed_ = true;
}

void RaycastingScene::buildCountingScene() {
  {
    std::shared_lock lock(mutex_);
    if (countingBuilt_) return;
  }
  std::unique_lock lock(mutex_);
  if (countingBuilt_) return;
  app::Scene counting = app::newScene(device_.get());
  rtcSetSceneFlags(counting.get(), RTC_SCENE_FLAG_ROBUST);
  for (std::size_t id = 0; id < revolutions_.size(); ++id) {
    if (Revolution* g = revolutions_[id].get()) {
      if (!g->countingGeometry) {
        g->countingGeometry.emplace(device_.get(), g->shape);
        g->countingGeometry->setIntersectFilter(countCrossing);
        rtcCommitGeometry(g->countingGeometry->handle());
      }
      g->countingPrototype.reset();
      attach(device_.get(), counting.get(), *g->countingGeometry, g->countingPrototype, g->placement, unsigned(id));
    } else {
      const Mesh& mesh = *meshes_[id];
      RTCGeometry geometry = rtcNewGeometry(device_.get(), RTC_GEOMETRY_TYPE_TRIANGLE);
      rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, mesh.vertices.data(), 0,
                                 3 * sizeof(float), mesh.vertexCount);
      rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh.triangles.data(), 0,
                                 3 * sizeof(std::uint32_t), mesh.triangleCount);
      rtcSetGeometryIntersectFilterFunction(geometry, countCrossing);
      rtcCommitGeometry(geometry);
      rtcAttachGeometryByID(counting.get(), geometry, unsigned(id));
      rtcReleaseGeometry(geometry);
    }
  }
  rtcCommitScene(counting.get());
  if (rtcGetDeviceError(device_.get()) != RTC_ERROR_NONE) throw std::runtime_error("Embree failed to build the scene");
  counting_ = std::move(counting);
  countingBuilt_ = true;
}

template <class Body>
std::optional<std::size_t> RaycastingScene::forEach(const float* items, std::size_t count, std::size_t width, bool rays,
                                                    int threads, Body body) {
  std::atomic<std::size_t> firstRefused{std::numeric_limits<std::size_t>::max()};
  std::shared_lock lock(mutex_);
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1024),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        embree::RayQuery query;
                        for (std::size_t i = range.begin(); i != range.end(); ++i) {
                          const float* item = items + width * i;
                          if (!(rays ? rayAccepted(item) : pointAccepted(item))) {
                            recordMinimum(firstRefused, i);
                            continue;
                          }
                          body(query, i, item);
                        }
                      });
  });
  const std::size_t first = firstRefused.load();
  if (first == std::numeric_limits<std::size_t>::max()) return std::nullopt;
  return first;
}

std::optional<std::size_t> RaycastingScene::castRays(const float* rays, std::size_t count, const Hits& out,
                                                     int threads) {
  commitIfChanged();
  RTCScene top = top_.get();
  return forEach(rays, count, 6, true, threads, [&](embree::RayQuery& query, std::size_t i, const float* r) {
    RTCRayHit rh = embree::newRayHit(r[0], r[1], r[2], r[3], r[4], r[5], 0.0f, kInfinity);
    query.intersect(top, rh);
    float* uv = out.uv + 2 * i;
    float* normal = out.normal + 3 * i;
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
      out.t[i] = kInfinity;
      out.geometry[i] = out.primitive[i] = kInvalidId;
      uv[0] = uv[1] = 0;
      normal[0] = normal[1] = normal[2] = 0;
      return;
    }
    out.t[i] = rh.ray.tfar;
    out.primitive[i] = rh.hit.primID;
    uv[0] = rh.hit.u;
    uv[1] = rh.hit.v;
    const bool instanced = rh.hit.instID[0] != RTC_INVALID_GEOMETRY_ID;
    const unsigned id = instanced ? rh.hit.instID[0] : rh.hit.geomID;
    out.geometry[i] = id;
    if (instanced) {
      // A placed revolution: its unit object-space normal carried to the world.
      const Vec3d n = revolutions_[id]->placement.normalToWorld({rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z});
      normal[0] = float(n[0]), normal[1] = float(n[1]), normal[2] = float(n[2]);
    } else if (revolutions_[id]) {
      normal[0] = rh.hit.Ng_x, normal[1] = rh.hit.Ng_y, normal[2] = rh.hit.Ng_z;  // unit already, in the world
    } else {
      // A triangle: Embree's normal made unit length as Open3D does it, in float.
      const float scale =
          1.0f / std::sqrt(rh.hit.Ng_x * rh.hit.Ng_x + rh.hit.Ng_y * rh.hit.Ng_y + rh.hit.Ng_z * rh.hit.Ng_z);
      normal[0] = rh.hit.Ng_x * scale, normal[1] = rh.hit.Ng_y * scale, normal[2] = rh.hit.Ng_z * scale;
    }
  });
}

std::optional<std::size_t> RaycastingScene::testOcclusions(const float* rays, std::size_t count, float tnear,
                                                           float tfar, bool* out, int threads) {
  commitIfChanged();
  RTCScene top = top_.get();
  return forEach(rays, count, 6, true, threads, [&](embree::RayQuery& query, std::size_t i, const float* r) {
    RTCRay ray = embree::newRayHit(r[0], r[1], r[2], r[3], r[4], r[5], tnear, tfar).ray;
    query.occluded(top, ray);
    out[i] = ray.tfar == -kInfinity;
  });
}

std::optional<std::size_t> RaycastingScene::countIntersections(const float* rays, std::size_t count, std::int32_t* out,
                                                               int threads) {
  commitIfChanged();
  buildCountingScene();
  RTCScene counting = counting_.get();
  return forEach(rays, count, 6, true, threads, [&](embree::RayQuery& query, std::size_t i, const float* r) {
    CrossingCount tally;
    crossings = &tally;
    RTCRayHit rh = embree::newRayHit(r[0], r[1], r[2], r[3], r[4], r[5], 0.0f, kInfinity);
    query.intersect(counting, rh);
    crossings = nullptr;
    out[i] = tally.count;
  });
}

std::string RaycastingScene::distanceLimitation() const {
  std::shared_lock lock(mutex_);
  for (std::size_t id = 0; id < revolutions_.size(); ++id) {
    if (revolutions_[id] && revolutions_[id]->placement.similarity == 0) {
      return "geometry " + std::to_string(id) +
             " is placed by a transform that is not a similarity (rotation, uniform scale, translation), under which "
             "its "
             "distances cannot be taken exactly in its meridian plane; scale the profile's r and z instead";
    }
  }
  return "";
}

std::string RaycastingScene::solidLimitation() const {
  std::shared_lock lock(mutex_);
  for (std::size_t id = 0; id < revolutions_.size(); ++id) {
    if (!revolutions_[id]) {
      return "geometry " + std::to_string(id) +
             " is a triangle mesh; revolve decides inside and outside from closed profiles only (Open3D's "
             "RaycastingScene "
             "votes with rays for meshes)";
    }
    const Shape& shape = revolutions_[id]->shape;
    const bool closed = shape.spline() != nullptr ? shape.spline()->closed() : shape.profile().closed();
    if (!closed) {
      return "geometry " + std::to_string(id) +
             "'s profile is open (its ends neither meet nor both lie on the axis), so it bounds no solid";
    }
  }
  return "";
}

std::optional<std::size_t> RaycastingScene::closestPoints(const float* points, std::size_t count, const Closest& out,
                                                          bool signedDistance, int threads) {
  commitIfChanged();
  RTCScene top = top_.get();
  return forEach(points, count, 3, false, threads, [&](embree::RayQuery&, std::size_t i, const float* p) {
    PointQuery q{&revolutions_, &meshes_, {p[0], p[1], p[2]}, {}};
    RTCPointQuery query{};
    query.x = p[0], query.y = p[1], query.z = p[2];
    query.radius = kInfinity;
    query.time = 0;
    RTCPointQueryContext context;
    rtcInitPointQueryContext(&context);
    rtcPointQuery(top, &query, &context, pointQueryCallback, &q);
    const Candidate& best = q.best;
    double distance = best.distance;
    if (signedDistance) {
      for (const auto& g : revolutions_) {
        const Vec3d local = g->placement.toObject(q.query);
        if (insideSolid(g->shape, std::hypot(local[0], local[1]), local[2])) {
          distance = -distance;
          break;
        }
      }
    }
    for (int k = 0; k < 3; ++k) {
      out.point[3 * i + k] = float(best.point[k]);
      out.normal[3 * i + k] = float(best.normal[k]);
    }
    out.uv[2 * i] = float(best.u);
    out.uv[2 * i + 1] = float(best.v);
    out.geometry[i] = best.geometry;
    out.primitive[i] = best.primitive;
    out.distance[i] = float(distance);
  });
}

std::optional<std::size_t> RaycastingScene::occupancy(const float* points, std::size_t count, float* out, int threads) {
  return forEach(points, count, 3, false, threads, [&](embree::RayQuery&, std::size_t i, const float* p) {
    bool inside = false;
    for (const auto& g : revolutions_) {
      const Vec3d local = g->placement.toObject({p[0], p[1], p[2]});
      if (insideSolid(g->shape, std::hypot(local[0], local[1]), local[2])) {
        inside = true;
        break;
      }
    }
    out[i] = inside ? 1.0f : 0.0f;
  });
}

}  // namespace revolve::python
