// One method at one resolution, built into its own Embree scene: what the benchmark times.
#pragma once

#include "analytic_sphere.h"
#include "smooth_profile.h"

#include <revolve/embree_baselines.h>
#include <revolve/revolve.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace revolve::bench {

// The shapes as polylines (SmoothProfile::sample: every arc's chords of one sagitta) for MIBIT, the
// baselines, meshes and embreeCone (Embree's linear cone curve); embreeRoundCurve is Embree's round
// Bézier curve fitted to the smooth profile (round_curve.h); the curve methods take a spline
// (smooth_spline.h):
//   spline: the spline traced exactly (default MIBIT);
//   adaptive: its polyline within a tolerance (Profile::fromCurve), traced by default MIBIT;
//   uniform: the curve sampled at even steps along it (SmoothProfile::sampleUniform), default MIBIT;
//   adaptiveMesh: the adaptive polyline tessellated.
enum class MethodKind {
  mibit,
  linear,
  kajiya,
  mesh,
  sphere,
  embreeCone,
  embreeRoundCurve,
  spline,
  adaptive,
  uniform,
  adaptiveMesh
};

struct MethodConfig {
  MethodKind kind = MethodKind::mibit;
  ShellKind shell = ShellKind::cylinder;  // MIBIT only
  // Profile points (not for the analytic sphere; for adaptive, found when built); Bézier segments
  // of a round curve.
  int points = 0;
  int slices = 0;        // meshes only
  bool binary = false;   // MIBIT with the paper's binary tree (BuildOptions::wideNodes off)
  double tolerance = 0;  // adaptive and adaptiveMesh: Profile::fromCurve's, relative to the size
  // "mibit", "mibit_binary", "mibit_cone", "mibit_hybrid", "linear", "kajiya", "mesh", "sphere",
  // "embree_cone", "embree_round_curve", "spline", "adaptive", "uniform", "mesh_adaptive"
  std::string method() const;
  std::string label() const;  // method and resolution, e.g. "mesh 64x128", "embree_round_curve 8 seg"
  // Embree's curves orient Ng away from their centre line whatever side the solid is on: their
  // normals are compared with the surface's up to sign.
  bool orientedNormals() const { return kind != MethodKind::embreeCone && kind != MethodKind::embreeRoundCurve; }
};

// Embree's own allocations on a device (rtcSetDeviceMemoryMonitorFunction), net of frees.
class MemoryMonitor {
 public:
  explicit MemoryMonitor(RTCDevice device);
  std::int64_t bytes() const { return bytes_.load(); }

 private:
  static bool record(void* user, ssize_t bytes, bool post);
  std::atomic<std::int64_t> bytes_{0};
};

// Why `config` cannot trace `profile` (Embree's curves cannot express every profile), or nothing.
std::optional<std::string> limitationOf(const SmoothProfile& profile, const MethodConfig& config);

class TracedScene {
 public:
  // The analytic sphere is built from `sphere`, the round curve from the smooth profile itself, the
  // curve methods from `spline` (the profile's), every other method from profile.sample(points).
  // Throws std::invalid_argument for a configuration limitationOf refuses.
  TracedScene(RTCDevice device, const MemoryMonitor& monitor, const SmoothProfile& profile, const Spline& spline,
              const MethodConfig& config, const AnalyticSphere& sphere)
      : TracedScene(device, monitor, profile, &spline, config, sphere) {}
  // A method other than the curve methods, which need no spline (std::invalid_argument for those).
  TracedScene(RTCDevice device, const MemoryMonitor& monitor, const SmoothProfile& profile, const MethodConfig& config,
              const AnalyticSphere& sphere)
      : TracedScene(device, monitor, profile, nullptr, config, sphere) {}
  ~TracedScene();
  TracedScene(const TracedScene&) = delete;
  TracedScene& operator=(const TracedScene&) = delete;

  RTCScene scene() const { return scene_; }
  const MethodConfig& config() const { return config_; }
  double buildSeconds() const { return buildSeconds_; }
  std::size_t revolveBytes() const { return revolveBytes_; }  // Shape::memoryBytes(); 0 for meshes
  std::int64_t embreeBytes() const { return embreeBytes_; }   // BVH and buffers, from the monitor
  std::uint64_t triangles() const { return triangles_; }
  int points() const { return points_; }  // the polyline's points (the spline's for an exact curve)

 private:
  TracedScene(RTCDevice device, const MemoryMonitor& monitor, const SmoothProfile& profile, const Spline* spline,
              const MethodConfig& config, const AnalyticSphere& sphere);

  MethodConfig config_;
  std::unique_ptr<Shape> shape_;
  std::unique_ptr<Geometry> geometry_;
  std::unique_ptr<ConeCurveGeometry> coneCurve_;
  AnalyticSphere sphere_;
  RTCScene scene_ = nullptr;
  double buildSeconds_ = 0.0;
  std::size_t revolveBytes_ = 0;
  std::int64_t embreeBytes_ = 0;
  std::uint64_t triangles_ = 0;
  int points_ = 0;
};

}  // namespace revolve::bench
