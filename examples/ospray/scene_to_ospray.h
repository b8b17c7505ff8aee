// A scene file's contents (platform/io/scene_file.h) as OSPRay objects: its revolutions as the
// revolve module's "revolution" geometries (one per profile, placed by instances), its quads as
// one OSPRay mesh, its materials as OSPRay "obj" materials, its lights and environment as OSPRay
// lights, its camera as OSPRay's perspective camera. The module must be loaded first.
#pragma once

#include "io/scene_file.h"

#include <ospray/ospray.h>

#include <cstdint>
#include <vector>

namespace revolve::ospray_example {

// Owns its OSPRay handles; releases them when it goes.
class OsprayScene {
 public:
  // meshSlices > 0: each profile as an OSPRay triangle mesh of that many azimuthal steps instead
  // (revolve's tessellation, the baseline its benchmarks use), to compare against the exact surfaces.
  OsprayScene(const io::SceneDescription& scene, int width, int height, std::uint32_t meshSlices = 0);
  ~OsprayScene();
  OsprayScene(const OsprayScene&) = delete;
  OsprayScene& operator=(const OsprayScene&) = delete;

  OSPWorld world() const { return world_; }
  OSPCamera camera() const { return camera_; }
  // The world's instances: one per scene object, in the scene's order, then the quads' (if any);
  // each has its index here as its OSPRay "id".
  const std::vector<OSPInstance>& instances() const { return instances_; }
  // Bytes of the surfaces' own description handed to OSPRay: revolve's shapes (search trees), or
  // the meshes' vertices and indices. OSPRay's BVH over them is not included.
  std::size_t geometryBytes() const { return geometryBytes_; }

 private:
  OSPObject keep(OSPObject object);  // released by the destructor
  std::vector<OSPObject> owned_;
  std::vector<OSPInstance> instances_;
  OSPWorld world_ = nullptr;
  OSPCamera camera_ = nullptr;
  std::size_t geometryBytes_ = 0;
};

}  // namespace revolve::ospray_example
