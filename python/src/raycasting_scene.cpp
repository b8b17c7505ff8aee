#include "raycasting_scene.h"

#include "geometry/ray_limits.h"
#include "threads/thread_arenas.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace revolve::python {

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// count_intersections: the counter of the ray the calling thread traces (a filter function runs on
// the thread that called rtcIntersect1), and the crossing it saw last. list_intersections traces
// each ray a second time with `list` set: its crossings are written there, `capacity` of them at
// most (the count of the first pass, which the same traversal repeats).
struct CrossingCount {
  std::int32_t count = 0;
  unsigned geometry = RTC_INVALID_GEOMETRY_ID;
  float t = 0;
  RaycastingScene::Crossing* list = nullptr;
  std::int32_t capacity = 0;
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
      if (c.list != nullptr && c.count < c.capacity) {
        c.list[c.count] = {t, geometry, RTCHitN_primID(args->hit, args->N, i), RTCHitN_u(args->hit, args->N, i),
                           RTCHitN_v(args->hit, args->N, i)};
      }
      ++c.count;
      c.geometry = geometry, c.t = t;
    }
  }
}

using app::cross;
using app::dot;
using app::minus;
using app::Vec3d;

// The closest point so far of a point query, in double.
struct Candidate {
  double distance = std::numeric_limits<double>::infinity();
  Vec3d point{}, normal{};
  double u = 0, v = 0;
  std::uint32_t geometry = RTC_INVALID_GEOMETRY_ID, primitive = RTC_INVALID_GEOMETRY_ID;
};

struct PointQuery {
  const scene::EmbreeScene* scene;
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

void offerTriangle(PointQuery& q, const scene::TriangleMesh& mesh, unsigned id, unsigned primitive) {
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

void offerRevolution(PointQuery& q, const Shape& shape, const app::Placement& placement, unsigned id) {
  const Vec3d local = placement.toObject(q.query);
  const double rho = std::hypot(local[0], local[1]);
  const MeridianPoint m = closestMeridianPoint(shape, {rho, local[2]});
  const double distance = m.distance * placement.similarity();
  if (!(distance < q.best.distance)) return;
  // The meridian half-plane of the query (any, on the axis).
  const double cx = rho > 0 ? local[0] / rho : 1, cy = rho > 0 ? local[1] / rho : 0;
  const std::span<const Point2> points = shape.profile().points();
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
  const std::span<const double> arc = shape.profile().arcLength();
  const double turns = std::atan2(local[1], local[0]) * (0.5 / std::numbers::pi);
  q.best.distance = distance;
  q.best.point = placement.toWorld({m.point.r * cx, m.point.r * cy, m.point.z});
  q.best.normal = placement.normalToWorld({nr * cx, nr * cy, nz});
  q.best.u = turns < 0 ? turns + 1 : turns;
  q.best.v = (arc[m.segment] + along * (arc[m.segment + 1] - arc[m.segment])) / arc.back();
  q.best.geometry = id;
  q.best.primitive = m.segment;
}

bool pointQueryCallback(RTCPointQueryFunctionArguments* args) {
  auto& q = *static_cast<PointQuery*>(args->userPtr);
  const double before = q.best.distance;
  const unsigned id = args->context->instStackSize > 0 ? args->context->instID[0] : args->geomID;
  if (const Shape* shape = q.scene->shapeOf(id)) {
    offerRevolution(q, *shape, q.scene->placementOf(id), id);
  } else {
    offerTriangle(q, *q.scene->meshOf(id), id, args->primID);
  }
  if (!(q.best.distance < before)) return false;
  // The radius shrinks to the best distance, rounded up so that it never excludes the best.
  args->query->radius = std::nextafter(float(q.best.distance), kInfinity);
  return true;
}

void recordMinimum(std::atomic<std::size_t>& first, std::size_t index) {
  std::size_t seen = first.load(std::memory_order_relaxed);
  while (index < seen && !first.compare_exchange_weak(seen, index, std::memory_order_relaxed)) {}
}

}  // namespace

RaycastingScene::RaycastingScene() : scene_(scene::Layout{.robust = true}) {}

std::uint32_t RaycastingScene::addRevolution(Shape shape, const app::Placement& placement) {
  std::unique_lock lock(mutex_);
  const std::uint32_t id = scene_.addRevolution(std::move(shape), placement);
  recipes_.resize(std::size_t(id) + 1);
  committed_ = false;
  countingCurrent_ = false;
  return id;
}

std::uint32_t RaycastingScene::addTriangles(std::span<const float> vertices, std::span<const std::uint32_t> triangles) {
  std::unique_lock lock(mutex_);
  const std::uint32_t id = scene_.addTriangles(vertices, triangles);
  recipes_.resize(std::size_t(id) + 1);
  committed_ = false;
  countingCurrent_ = false;
  return id;
}

std::uint32_t RaycastingScene::addRevolution(Shape shape, const app::Placement& placement, RevolutionRecipe recipe) {
  std::unique_lock lock(mutex_);
  const std::uint32_t id = scene_.addRevolution(std::move(shape), placement);
  recipes_.resize(std::size_t(id) + 1);
  recipes_[id] = std::move(recipe);
  committed_ = false;
  countingCurrent_ = false;
  return id;
}

std::uint32_t RaycastingScene::addRevolutions(std::vector<Shape> shapes, std::span<const app::Placement> placements,
                                              std::vector<RevolutionRecipe> recipes) {
  std::unique_lock lock(mutex_);
  const std::size_t count = shapes.size();
  const std::uint32_t first = scene_.addRevolutions(std::move(shapes), placements);
  recipes_.resize(std::size_t(first) + count);
  for (std::size_t i = 0; i < count; ++i) recipes_[first + i] = std::move(recipes[i]);
  committed_ = false;
  countingCurrent_ = false;
  return first;
}

void RaycastingScene::forEachAddition(const std::function<void(const RevolutionRecipe&)>& revolution,
                                      const std::function<void(const scene::TriangleMesh&)>& mesh) const {
  std::shared_lock lock(mutex_);
  for (std::uint32_t id = 0; id < scene_.geometryCount(); ++id) {
    if (const scene::TriangleMesh* triangles = scene_.meshOf(id)) {
      mesh(*triangles);
    } else if (id < recipes_.size() && recipes_[id]) {
      revolution(*recipes_[id]);
    } else {
      throw std::logic_error("geometry " + std::to_string(id) + " was added without what rebuilds it");
    }
  }
}

std::size_t RaycastingScene::geometryCount() const {
  std::shared_lock lock(mutex_);
  return scene_.geometryCount();
}

std::size_t RaycastingScene::memoryBytes() const {
  std::shared_lock lock(mutex_);
  return std::size_t(std::max<std::int64_t>(0, scene_.embreeBytes())) + scene_.revolveBytes() + scene_.meshBytes() +
         recipeBytes();
}

std::size_t RaycastingScene::recipeBytes() const noexcept {
  std::size_t bytes = recipes_.capacity() * sizeof(std::optional<RevolutionRecipe>);
  for (const std::optional<RevolutionRecipe>& recipe : recipes_) {
    if (recipe) bytes += recipe->points.capacity() * sizeof(double) + (recipe->spline ? recipe->spline->capacity() : 0);
  }
  return bytes;
}

RaycastingScene::QueryLock RaycastingScene::readyForQueries(bool counting) {
  for (;;) {
    QueryLock shared(mutex_);
    if (committed_ && (!counting || countingCurrent_)) return shared;
    shared.unlock();
    // Commit (and build the counting copy) alone; then take the shared lock again and look once more,
    // since an addition may have come in between.
    std::unique_lock exclusive(mutex_);
    if (!committed_) {
      scene_.commit();
      committed_ = true;
    }
    if (counting && !countingCurrent_) {
      counting_ = scene_.filteredScene(countCrossing);
      countingCurrent_ = true;
    }
  }
}

template <class Body>
std::optional<std::size_t> RaycastingScene::forEach(const float* items, std::size_t count, bool rays, int threads,
                                                    Body body) const {
  std::atomic<std::size_t> firstRefused{std::numeric_limits<std::size_t>::max()};
  const std::size_t width = rays ? 6 : 3;
  app::threadArena(threads).execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1024),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        embree::RayQuery query;
                        for (std::size_t i = range.begin(); i != range.end(); ++i) {
                          const float* item = items + width * i;
                          if (!(rays ? app::queryRayAccepted(item) : app::queryPointAccepted(item))) {
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
  const QueryLock lock = readyForQueries(false);
  RTCScene top = scene_.handle();
  return forEach(rays, count, true, threads, [&](embree::RayQuery& query, std::size_t i, const float* r) {
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
    const unsigned id = rh.hit.instID[0] != RTC_INVALID_GEOMETRY_ID ? rh.hit.instID[0] : rh.hit.geomID;
    out.geometry[i] = id;
    if (!scene_.worldNormals(id)) {
      // A placed revolution: its unit object-space normal carried to the world.
      const Vec3d n = scene_.placementOf(id).normalToWorld({rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z});
      normal[0] = float(n[0]), normal[1] = float(n[1]), normal[2] = float(n[2]);
    } else if (scene_.shapeOf(id) != nullptr) {
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
  const QueryLock lock = readyForQueries(false);
  RTCScene top = scene_.handle();
  return forEach(rays, count, true, threads, [&](embree::RayQuery& query, std::size_t i, const float* r) {
    RTCRay ray = embree::newRayHit(r[0], r[1], r[2], r[3], r[4], r[5], tnear, tfar).ray;
    query.occluded(top, ray);
    out[i] = ray.tfar == -kInfinity;
  });
}

std::optional<std::size_t> RaycastingScene::listIntersections(const float* rays, std::size_t count,
                                                              const std::function<Crossing*(std::size_t)>& allocate,
                                                              std::vector<std::uint32_t>& splits, int threads) {
  std::vector<std::int32_t> counts(count);
  const QueryLock lock = readyForQueries(true);
  RTCScene counting = counting_;
  const auto trace = [&](embree::RayQuery& query, const float* r, CrossingCount& tally) {
    crossings = &tally;
    RTCRayHit rh = embree::newRayHit(r[0], r[1], r[2], r[3], r[4], r[5], 0.0f, kInfinity);
    query.intersect(counting, rh);
    crossings = nullptr;
  };
  const std::optional<std::size_t> refused =
      forEach(rays, count, true, threads, [&](embree::RayQuery& query, std::size_t i, const float* r) {
        CrossingCount tally;
        trace(query, r, tally);
        counts[i] = tally.count;
      });
  if (refused) return refused;
  splits.assign(count + 1, 0);
  std::uint64_t total = 0;
  for (std::size_t i = 0; i < count; ++i) {
    splits[i] = std::uint32_t(total);
    total += std::uint64_t(counts[i]);
    if (total > std::numeric_limits<std::uint32_t>::max())
      throw std::length_error(
          "the rays cross surfaces more than 2^32 - 1 times (Open3D's uint32 ray_splits); split them");
  }
  splits[count] = std::uint32_t(total);
  Crossing* out = allocate(std::size_t(total));
  forEach(rays, count, true, threads, [&](embree::RayQuery& query, std::size_t i, const float* r) {
    CrossingCount tally;
    tally.list = out + splits[i];
    tally.capacity = counts[i];
    trace(query, r, tally);
    // Nearest first; equal t by geometry, then primitive, so that the order is the same every run.
    std::sort(tally.list, tally.list + std::min(tally.count, tally.capacity), [](const Crossing& a, const Crossing& b) {
      return a.t != b.t ? a.t < b.t : a.geometry != b.geometry ? a.geometry < b.geometry : a.primitive < b.primitive;
    });
  });
  return std::nullopt;
}

std::optional<std::size_t> RaycastingScene::countIntersections(const float* rays, std::size_t count, std::int32_t* out,
                                                               int threads) {
  const QueryLock lock = readyForQueries(true);
  RTCScene counting = counting_;
  return forEach(rays, count, true, threads, [&](embree::RayQuery& query, std::size_t i, const float* r) {
    CrossingCount tally;
    crossings = &tally;
    RTCRayHit rh = embree::newRayHit(r[0], r[1], r[2], r[3], r[4], r[5], 0.0f, kInfinity);
    query.intersect(counting, rh);
    crossings = nullptr;
    out[i] = tally.count;
  });
}

std::string RaycastingScene::distanceLimitation() const {
  for (std::uint32_t id = 0; id < scene_.geometryCount(); ++id) {
    if (scene_.shapeOf(id) != nullptr && scene_.placementOf(id).similarity() == 0) {
      return "geometry " + std::to_string(id) +
             " is placed by a transform that is not a similarity (rotation, uniform scale, translation), under which "
             "its distances cannot be taken exactly in its meridian plane; scale the profile's r and z instead";
    }
  }
  return "";
}

std::string RaycastingScene::solidLimitation() const {
  for (std::uint32_t id = 0; id < scene_.geometryCount(); ++id) {
    const Shape* shape = scene_.shapeOf(id);
    if (shape == nullptr) {
      return "geometry " + std::to_string(id) +
             " is a triangle mesh; revolve decides inside and outside from closed profiles only (Open3D's "
             "RaycastingScene votes with rays for meshes)";
    }
    if (!shape->closed()) {
      return "geometry " + std::to_string(id) +
             "'s profile is open (its ends neither meet nor both lie on the axis), so it bounds no solid";
    }
  }
  return "";
}

std::optional<std::size_t> RaycastingScene::closestPoints(const float* points, std::size_t count, const Closest& out,
                                                          bool signedDistance, int threads) {
  const QueryLock lock = readyForQueries(false);
  std::string limitation = distanceLimitation();
  if (limitation.empty() && signedDistance) limitation = solidLimitation();
  if (!limitation.empty()) throw std::invalid_argument(limitation);
  RTCScene top = scene_.handle();
  return forEach(points, count, false, threads, [&](embree::RayQuery&, std::size_t i, const float* p) {
    PointQuery q{&scene_, {p[0], p[1], p[2]}, {}};
    RTCPointQuery query{};
    query.x = p[0], query.y = p[1], query.z = p[2];
    query.radius = kInfinity;
    query.time = 0;
    RTCPointQueryContext context;
    rtcInitPointQueryContext(&context);
    rtcPointQuery(top, &query, &context, pointQueryCallback, &q);
    const Candidate& best = q.best;
    double distance = best.distance;
    if (signedDistance && insideAny(q.query)) distance = -distance;
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

bool RaycastingScene::insideAny(const Vec3d& p) const noexcept {
  for (std::uint32_t id = 0; id < scene_.geometryCount(); ++id) {
    const Vec3d local = scene_.placementOf(id).toObject(p);
    if (insideSolid(*scene_.shapeOf(id), {std::hypot(local[0], local[1]), local[2]})) return true;
  }
  return false;
}

std::optional<std::size_t> RaycastingScene::occupancy(const float* points, std::size_t count, float* out, int threads) {
  const QueryLock lock = readyForQueries(false);
  if (const std::string limitation = solidLimitation(); !limitation.empty()) throw std::invalid_argument(limitation);
  return forEach(points, count, false, threads, [&](embree::RayQuery&, std::size_t i, const float* p) {
    out[i] = insideAny({p[0], p[1], p[2]}) ? 1.0f : 0.0f;
  });
}

}  // namespace revolve::python
