#include "traced_scene.h"
#include <revolve/embree_baselines.h>

#include "round_curve.h"

#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <variant>

namespace revolve::bench {

std::string MethodConfig::method() const {
  switch (kind) {
    case MethodKind::mibit:
      if (shell == ShellKind::cylinder) return binary ? "mibit_binary" : "mibit";
      return shell == ShellKind::cone ? "mibit_cone" : "mibit_hybrid";
    case MethodKind::linear:
      return "linear";
    case MethodKind::kajiya:
      return "kajiya";
    case MethodKind::mesh:
      return "mesh";
    case MethodKind::sphere:
      return "sphere";
    case MethodKind::embreeCone:
      return "embree_cone";
    case MethodKind::embreeRoundCurve:
      return "embree_round_curve";
    case MethodKind::spline:
      return "spline";
    case MethodKind::adaptive:
      return "adaptive";
    case MethodKind::uniform:
      return "uniform";
    case MethodKind::adaptiveMesh:
      return "mesh_adaptive";
  }
  return "?";
}

std::string MethodConfig::label() const {
  char tolerance[16];
  std::snprintf(tolerance, sizeof tolerance, "%.0e", this->tolerance);
  switch (kind) {
    case MethodKind::sphere:
      return "analytic sphere";
    case MethodKind::mesh:
      return "mesh " + std::to_string(points) + "x" + std::to_string(slices);
    case MethodKind::spline:
      return "spline exact";
    case MethodKind::adaptive:
      return "adaptive " + std::string(tolerance) + " (" + std::to_string(points) + ")";
    case MethodKind::adaptiveMesh:
      return "mesh adapt " + std::string(tolerance) + " " + std::to_string(points) + "x" + std::to_string(slices);
    case MethodKind::embreeRoundCurve:
      return method() + " " + std::to_string(points) + " seg";
    default:
      return method() + " " + std::to_string(points);
  }
}

std::optional<std::string> limitationOf(const SmoothProfile& profile, const MethodConfig& config) {
  if (config.kind == MethodKind::embreeCone) return coneCurveLimitation(Profile(profile.sample(config.points)));
  if (config.kind == MethodKind::embreeRoundCurve) {
    auto fit = fitRoundCurve(profile, config.points);
    if (auto* reason = std::get_if<std::string>(&fit)) return *reason;
  }
  return std::nullopt;
}

MemoryMonitor::MemoryMonitor(RTCDevice device) { rtcSetDeviceMemoryMonitorFunction(device, record, this); }

bool MemoryMonitor::record(void* user, ssize_t bytes, bool /*post*/) {
  static_cast<MemoryMonitor*>(user)->bytes_.fetch_add(bytes);
  return true;
}

TracedScene::TracedScene(RTCDevice device, const MemoryMonitor& monitor, const SmoothProfile& profile,
                         const Spline* splineOrNull, const MethodConfig& config, const AnalyticSphere& sphere)
    : config_(config), sphere_(sphere) {
  const bool curveMethod = config.kind == MethodKind::spline || config.kind == MethodKind::adaptive ||
                           config.kind == MethodKind::uniform || config.kind == MethodKind::adaptiveMesh;
  if (curveMethod && splineOrNull == nullptr)
    throw std::invalid_argument(config.method() + " needs the profile's spline");
  const std::int64_t before = monitor.bytes();
  const auto start = std::chrono::steady_clock::now();
  scene_ = rtcNewScene(device);
  if (scene_ == nullptr) throw std::runtime_error("rtcNewScene failed");
  RTCGeometry geometry = nullptr;
  switch (config.kind) {
    case MethodKind::sphere:
      geometry = newAnalyticSphereGeometry(device, sphere_);
      break;
    case MethodKind::embreeCone:
      coneCurve_ = std::make_unique<ConeCurveGeometry>(device, Profile(profile.sample(config.points)));
      points_ = config.points;
      break;
    case MethodKind::embreeRoundCurve: {
      auto fit = fitRoundCurve(profile, config.points);
      if (auto* reason = std::get_if<std::string>(&fit)) throw std::invalid_argument(*reason);
      attachRoundCurve(device, scene_, std::get<RoundCurveFit>(fit));
      points_ = config.points;  // its segments
      break;
    }
    case MethodKind::mesh:
    case MethodKind::adaptiveMesh: {
      const Profile polyline = config.kind == MethodKind::mesh
                                   ? Profile(profile.sample(config.points))
                                   : Profile::fromCurve(*splineOrNull, config.tolerance * profile.size());
      geometry = newTessellatedGeometry(device, polyline, std::uint32_t(config.slices));
      triangles_ = 2ull * polyline.segmentCount() * std::uint64_t(config.slices);
      points_ = int(polyline.points().size());
      break;
    }
    case MethodKind::spline:
    case MethodKind::adaptive:
    case MethodKind::uniform: {
      if (config.kind == MethodKind::spline) {
        shape_ = std::make_unique<Shape>(*splineOrNull);
        points_ = int(splineOrNull->points().size());
      } else {
        Profile polyline = config.kind == MethodKind::adaptive
                               ? Profile::fromCurve(*splineOrNull, config.tolerance * profile.size())
                               : Profile(profile.sampleUniform(config.points));
        points_ = int(polyline.points().size());
        shape_ = std::make_unique<Shape>(std::move(polyline));
      }
      geometry_ = std::make_unique<Geometry>(device, *shape_);
      revolveBytes_ = shape_->memoryBytes();
      break;
    }
    default: {
      points_ = config.points;
      BuildOptions options;
      options.method = config.kind == MethodKind::linear   ? Method::linear
                       : config.kind == MethodKind::kajiya ? Method::kajiya
                                                           : Method::mibit;
      options.shell = config.shell;
      options.wideNodes = !config.binary;
      shape_ = std::make_unique<Shape>(Profile(profile.sample(config.points)), options);
      geometry_ = std::make_unique<Geometry>(device, *shape_);
      revolveBytes_ = shape_->memoryBytes();
      break;
    }
  }
  if (geometry != nullptr) {
    rtcAttachGeometry(scene_, geometry);
    rtcReleaseGeometry(geometry);  // the scene holds it
  } else if (geometry_ != nullptr) {
    rtcAttachGeometry(scene_, geometry_->handle());
  } else if (coneCurve_ != nullptr) {
    rtcAttachGeometry(scene_, coneCurve_->handle());
  }
  rtcCommitScene(scene_);
  buildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  embreeBytes_ = monitor.bytes() - before;
}

TracedScene::~TracedScene() {
  if (scene_ != nullptr) rtcReleaseScene(scene_);
}

}  // namespace revolve::bench
