#include "robot/clearance_map.h"

#include "robot/triangle_clearance.h"

#include <cmath>
#include <optional>
#include <stdexcept>

namespace revolve::robot {

struct ClearanceMap::Obstacle {
  std::int64_t object;
  std::optional<PlacedShape> shape;  // or, for a quad's triangle:
  std::array<Vec3d, 3> triangle{};
  Box box;
};

namespace {

// Embree boxes are floats: round outwards so that each still holds its obstacle.
float down(double x) {
  const float f = float(x);
  return double(f) > x ? std::nextafter(f, -INFINITY) : f;
}
float up(double x) {
  const float f = float(x);
  return double(f) < x ? std::nextafter(f, INFINITY) : f;
}

void boundsOf(const RTCBoundsFunctionArguments* args) {
  const auto& obstacles = *static_cast<const std::vector<ClearanceMap::Obstacle>*>(args->geometryUserPtr);
  const Box& box = obstacles[args->primID].box;
  *args->bounds_o = {down(box.lower[0]), down(box.lower[1]), down(box.lower[2]), 0.0f,
                     up(box.upper[0]),   up(box.upper[1]),   up(box.upper[2]),   0.0f};
}

// The BVH serves point queries only; rays never reach it.
void noIntersection(const RTCIntersectFunctionNArguments*) {}
void noOcclusion(const RTCOccludedFunctionNArguments*) {}

// Ties go to the lowest object index, so the answer does not depend on the BVH's visiting order.
void keep(SceneClearance& best, const ObstacleClearance& found, std::int64_t object) {
  const bool better =
      found.value < best.clearance || (found.value == best.clearance && best.object >= 0 && object < best.object);
  if (!better) return;
  best.clearance = found.value;
  best.collides = found.value < 0;
  best.object = object;
  best.point = found.point;
  best.exact = found.exact;
}

}  // namespace

ClearanceMap::ClearanceMap(const io::SceneDescription& scene, double ground)
    : device_(app::newDevice()), scene_(app::newScene(device_.get())) {
  std::vector<const Shape*> shapeOf(scene.profiles.size(), nullptr);
  for (const io::SceneObject& object : scene.objects) {
    if (shapeOf[object.profile] == nullptr) {
      const io::SceneProfile& profile = scene.profiles[object.profile];
      shapes_.push_back(profile.spline ? std::make_unique<Shape>(*profile.spline)
                                       : std::make_unique<Shape>(*profile.profile));
      shapeOf[object.profile] = shapes_.back().get();
    }
  }
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    Obstacle obstacle{
        std::int64_t(i), PlacedShape(*shapeOf[scene.objects[i].profile], scene.objects[i].transform), {}, {}};
    obstacle.box = obstacle.shape->worldBox();
    // The box is padded outwards, so an object reaching exactly down to the ground is not left out.
    if (obstacle.box.upper[2] <= ground) continue;
    obstacles_.push_back(std::move(obstacle));
  }
  for (std::size_t q = 0; q < scene.quads.size(); ++q) {
    const auto& c = scene.quads[q].corners;
    for (const auto& [a, b] : {std::pair{1, 2}, std::pair{2, 3}}) {  // as drawn: (0, 1, 2) and (0, 2, 3)
      Obstacle obstacle{std::int64_t(scene.objects.size() + q), std::nullopt, {c[0], c[a], c[b]}, {}};
      for (int axis = 0; axis < 3; ++axis) {
        obstacle.box.lower[axis] = std::min({c[0][axis], c[a][axis], c[b][axis]});
        obstacle.box.upper[axis] = std::max({c[0][axis], c[a][axis], c[b][axis]});
      }
      if (obstacle.box.upper[2] <= ground) continue;
      obstacles_.push_back(obstacle);
    }
  }
  if (obstacles_.empty()) return;
  RTCGeometry boxes = rtcNewGeometry(device_.get(), RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(boxes, unsigned(obstacles_.size()));
  rtcSetGeometryUserData(boxes, &obstacles_);
  rtcSetGeometryBoundsFunction(boxes, boundsOf, nullptr);
  rtcSetGeometryIntersectFunction(boxes, noIntersection);
  rtcSetGeometryOccludedFunction(boxes, noOcclusion);
  rtcCommitGeometry(boxes);
  rtcAttachGeometry(scene_.get(), boxes);
  rtcReleaseGeometry(boxes);
  rtcCommitScene(scene_.get());
  if (rtcGetDeviceError(device_.get()) != RTC_ERROR_NONE)
    throw std::runtime_error(scene.file + ": Embree failed to build the obstacles' BVH");
}

ClearanceMap::~ClearanceMap() = default;

std::size_t ClearanceMap::obstacleCount() const { return obstacles_.size(); }

ObstacleClearance ClearanceMap::obstacleClearance(std::size_t index, const RobotBody& robot) const {
  const Obstacle& obstacle = obstacles_[index];
  return obstacle.shape ? obstacle.shape->clearance(robot) : triangleClearance(robot, obstacle.triangle);
}

SceneClearance ClearanceMap::queryAll(const RobotBody& robot) const {
  SceneClearance best;
  for (std::size_t i = 0; i < obstacles_.size(); ++i) keep(best, obstacleClearance(i, robot), obstacles_[i].object);
  return best;
}

SceneClearance ClearanceMap::query(const RobotBody& robot) const {
  if (obstacles_.empty()) return {};
  struct State {
    const ClearanceMap* map;
    RobotBody robot;
    SceneClearance best;
  } state{this, robot, {}};
  const Vec3d centre = robot.centre();
  RTCPointQuery query;
  query.x = float(centre[0]);
  query.y = float(centre[1]);
  query.z = float(centre[2]);
  query.time = 0;
  query.radius = INFINITY;
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(
      scene_.get(), &query, &context,
      [](RTCPointQueryFunctionArguments* args) {
        auto& s = *static_cast<State*>(args->userPtr);
        const Obstacle& obstacle = s.map->obstacles_[args->primID];
        // The box bounds the obstacle's clearance from below: skip the exact work when it cannot win.
        if (signedDistance(s.robot, obstacle.box) > s.best.clearance) return false;  // (ties may win on index)
        keep(s.best, s.map->obstacleClearance(args->primID, s.robot), obstacle.object);
        // An obstacle with clearance c >= 0 has a point within c + reach of the centre; one with
        // c < 0 enters the robot, within its reach. So nothing beyond reach + max(best, 0) can win.
        // Rounded up: the query point is the float-rounded centre (within 2^-24 |centre| of it).
        const double radius = s.robot.reach() + std::max(s.best.clearance, 0.0);
        const Vec3d c = s.robot.centre();
        const float bound = up(radius + 0x1p-23 * (std::abs(c[0]) + std::abs(c[1]) + std::abs(c[2])));
        if (bound < args->query->radius) {
          args->query->radius = bound;
          return true;
        }
        return false;
      },
      &state);
  return state.best;
}

}  // namespace revolve::robot
