// revolve-bench scale: N distinct objects (scale_family.h) built as revolve's exact surfaces or as
// Embree meshes at matched error, through the scene stack the tools and Python share
// (scene/embree_scene.h): build time, memory, time to the first ray, and throughput on camera and
// lidar-like rays. One process measures one N and one geometry, so that its peak resident memory
// is that scene's (bench/python/plot_scale.py runs the ladder).
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

namespace revolve::bench {

struct ScaleSettings {
  std::size_t objects = 1000;
  bool mesh = false;  // Embree meshes instead of revolve's exact surfaces
  // Built by the library alone (scale_library.h: each object's Shape and placed Geometry in an
  // Embree scene) instead of through the tools' scene stack (a scene description, EmbreeScene).
  bool library = false;
  int cameraWidth = 512, cameraHeight = 256;
  int lidarAzimuths = 2048, lidarElevations = 32;  // a spinning lidar's beams: 32 rings, +-15 degrees
  int repetitions = 5;                             // of each throughput measurement (median reported)
  std::uint64_t seed = 20011;
  // A scene file to build instead of the family made in code (--scene; written by --write-scene):
  // the file's read (scene_file.h, object tables included) is timed apart from the build.
  std::string sceneFile;
};

// Builds the scene, traces, and returns the JSON record of the run (without the run's header).
nlohmann::ordered_json runScale(const ScaleSettings& settings);
// The table a reader sees, from that record.
void printScale(std::FILE* out, const nlohmann::ordered_json& record);

}  // namespace revolve::bench
