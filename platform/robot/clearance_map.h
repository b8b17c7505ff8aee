// The robot's clearance over a whole scene (io::SceneDescription): the least clearance over its
// objects of revolution (placed_shape.h: exact when upright, a lower bound when tilted) and its
// quads (triangle_clearance.h), with the obstacle that has it. An Embree BVH over the obstacles'
// world boxes, searched with a point query about the robot's centre whose radius shrinks to the
// best clearance so far plus the robot's reach, skips obstacles too far to matter.
#pragma once

#include "embree/embree_handles.h"
#include "io/scene_file.h"
#include "robot/placed_shape.h"
#include "robot/robot_body.h"

#include <revolve/revolve.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace revolve::robot {

struct SceneClearance {
  double clearance = INFINITY;  // signed (robot_body.h); +inf for a scene without obstacles
  bool collides = false;        // clearance < 0: the robot and an obstacle overlap
  std::int64_t object = -1;     // the scene's object index (quads: objects + quad index); -1: none
  Vec3d point{};                // a point of that obstacle's surface (robot_body.h, ObstacleClearance)
  bool exact = true;            // false: the clearance is a lower bound
};

class ClearanceMap {
 public:
  // Surfaces lying wholly at or below `ground` (world height) are the ground the robot drives on,
  // not obstacles: they are left out. The default leaves nothing out.
  explicit ClearanceMap(const io::SceneDescription& scene, double ground = -INFINITY);
  ~ClearanceMap();
  ClearanceMap(const ClearanceMap&) = delete;
  ClearanceMap& operator=(const ClearanceMap&) = delete;

  // Thread-safe.
  SceneClearance query(const RobotBody& robot) const;

  // Every obstacle in turn, without the BVH (for checking the search).
  SceneClearance queryAll(const RobotBody& robot) const;
  std::size_t obstacleCount() const;

  struct Obstacle;

 private:
  ObstacleClearance obstacleClearance(std::size_t index, const RobotBody& robot) const;

  std::vector<std::unique_ptr<Shape>> shapes_;  // one per profile used
  std::vector<Obstacle> obstacles_;
  app::Device device_;
  app::Scene scene_;
};

}  // namespace revolve::robot
