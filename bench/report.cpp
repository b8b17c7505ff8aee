#include "report.h"
#include <revolve/baselines.h>

#include "io/text_files.h"
#include "run_info.h"

#include <nlohmann/json.hpp>

#include <revolve/embree_api.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <sstream>
#include <thread>

namespace revolve::bench {
namespace {

using nlohmann::json;

std::string bytesText(double bytes) {
  char text[32];
  if (bytes >= 1e6)
    std::snprintf(text, sizeof text, "%.1f MB", bytes / 1e6);
  else
    std::snprintf(text, sizeof text, "%.1f KB", bytes / 1e3);
  return text;
}

const char* modeTitle(const std::string& mode) {
  if (mode == kIncoherent1) return "incoherent rays, rtcIntersect1, 1 thread";
  if (mode == kCamera1) return "camera rays, rtcIntersect1, 1 thread";
  if (mode == kCamera8) return "camera rays, rtcIntersect8, 1 thread";
  if (mode == kOccluded1) return "shadow rays: the incoherent rays, rtcOccluded1, 1 thread";
  if (mode == kOccluded8) return "shadow rays: the camera rays, rtcOccluded8, 1 thread";
  return "incoherent rays, rtcIntersect1, all threads";
}

json errorJson(const std::optional<ErrorSummary>& e) {
  if (!e) return nullptr;
  return {{"rays", e->rays},
          {"hits", e->hits},
          {"residual_max", e->residualMax},
          {"residual_p99", e->residualP99},
          {"residual_rms", e->residualRms},
          {"normal_max_degrees", e->normalMaxDegrees},
          {"normal_p99_degrees", e->normalP99Degrees},
          {"disagreements", e->disagreements},
          {"decided", e->decided},
          {"disagreement_fraction", e->disagreementFraction()},
          {"other_sheet", e->otherSheet},
          {"both_hit", e->bothHit},
          {"other_sheet_fraction", e->otherSheetFraction()}};
}

json configJson(const ConfigResult& c) {
  json speed = json::object();
  for (const auto& [mode, t] : c.speed) speed[mode] = {{"median", t.median}, {"low", t.low}, {"high", t.high}};
  return {{"method", c.config.method()},
          {"label", c.config.label()},
          {"limitation", c.limitation.empty() ? json(nullptr) : json(c.limitation)},
          {"points", c.config.points},
          {"slices", c.config.slices},
          {"tolerance", c.config.tolerance},
          {"triangles", c.triangles},
          {"build_seconds", c.buildSeconds},
          {"revolve_bytes", c.revolveBytes},
          {"embree_bytes", c.embreeBytes},
          {"total_bytes", c.totalBytes()},
          {"error_incoherent", errorJson(c.incoherent)},
          {"error_camera", errorJson(c.camera)},
          {"mrays_per_second", speed}};
}

json shapeJson(const ShapeResult& shape) {
  json configs = json::array();
  for (const ConfigResult& c : shape.configs) configs.push_back(configJson(c));
  json matched = json::array();
  for (const MatchedRow& row : shape.matched) {
    const auto pick = [&](const std::optional<std::size_t>& i) -> json {
      if (!i) return nullptr;
      const ConfigResult& c = shape.configs[*i];
      return {{"label", c.config.label()},
              {"mrays_per_second", c.speed.at(row.mode).median},
              {"residual_max", (row.mode.rfind("camera", 0) == 0 ? c.camera : c.incoherent)->residualMax},
              {"total_bytes", c.totalBytes()}};
    };
    json entry = {{"mode", row.mode},
                  {"level", row.level},
                  {"mibit", pick(row.mibit)},
                  {"mesh", pick(row.mesh)},
                  {"leanest_mibit", pick(row.leanestMibit)},
                  {"leanest_mesh", pick(row.leanestMesh)},
                  {"embree_cone", pick(row.embreeCone)},
                  {"embree_round_curve", pick(row.embreeRoundCurve)}};
    if (row.mibit && row.mesh) {
      entry["speed_ratio"] =
          shape.configs[*row.mibit].speed.at(row.mode).median / shape.configs[*row.mesh].speed.at(row.mode).median;
    }
    if (row.leanestMibit && row.leanestMesh) {
      entry["memory_ratio"] =
          shape.configs[*row.leanestMesh].totalBytes() / shape.configs[*row.leanestMibit].totalBytes();
    }
    matched.push_back(entry);
  }
  json points = json::array();
  for (const PointsRow& row : shape.points) {
    points.push_back({{"sample_points", row.samplePoints},
                      {"error", row.error},
                      {"adaptive_points", row.adaptivePoints},
                      {"uniform_points", row.uniformPoints}});
  }
  return {{"shape", shape.name},
          {"size", shape.size},
          {"spline_error", shape.splineError},
          {"spline_pieces", shape.splinePieces},
          {"polyline_points", points},
          {"incoherent_rays", shape.incoherentRays},
          {"camera_rays", shape.cameraRays},
          {"incoherent_grazing", shape.incoherentGrazing},
          {"camera_grazing", shape.cameraGrazing},
          {"configs", configs},
          {"matched", matched}};
}

void printShape(std::FILE* out, const ShapeResult& shape) {
  std::fprintf(
      out,
      "\n== %s (size %.3g; errors relative to it; %zu incoherent rays, %zu camera rays; errors, hits, hit/miss "
      "disagreements and hits on another sheet than the first (\"other\") of the incoherent rays)\n",
      shape.name.c_str(), shape.size, shape.incoherentRays, shape.cameraRays);
  std::fprintf(out, "%-25s %10s %10s %9s %9s %9s %8s | %8s %8s %8s %8s %8s %8s | %10s %10s %8s\n", "method", "err max",
               "err p99", "normal p99", "hits", "disagree", "other", "inc 1", "cam 1", "cam 8", "inc all", "occ 1",
               "occ 8", "revolve", "embree", "build ms");
  for (const ConfigResult& c : shape.configs) {
    if (!c.limitation.empty()) {
      std::fprintf(out, "%-25s cannot: %s\n", c.config.label().c_str(), c.limitation.c_str());
      continue;
    }
    const auto speed = [&](const char* mode) {
      const auto it = c.speed.find(mode);
      char text[16] = "-";
      if (it != c.speed.end()) std::snprintf(text, sizeof text, "%.3g", it->second.median);
      return std::string(text);
    };
    if (c.incoherent) {
      std::fprintf(out, "%-25s %10.2e %10.2e %8.3f° %9zu %8.4f%% %8zu |", c.config.label().c_str(),
                   c.incoherent->residualMax, c.incoherent->residualP99, c.incoherent->normalP99Degrees,
                   c.incoherent->hits, 100.0 * c.incoherent->disagreementFraction(), c.incoherent->otherSheet);
    } else {
      std::fprintf(out, "%-25s %10s %10s %9s %9s %9s %8s |", c.config.label().c_str(), "-", "-", "-", "-", "-", "-");
    }
    std::fprintf(out, " %8s %8s %8s %8s %8s %8s | %10s %10s %8.1f\n", speed(kIncoherent1).c_str(),
                 speed(kCamera1).c_str(), speed(kCamera8).c_str(), speed(kIncoherentAll).c_str(),
                 speed(kOccluded1).c_str(), speed(kOccluded8).c_str(), bytesText(double(c.revolveBytes)).c_str(),
                 bytesText(double(c.embreeBytes)).c_str(), 1e3 * c.buildSeconds);
  }
}

// "cannot" when the method traces none of the shape's configurations, else "none".
std::string noPick(const ShapeResult& shape, MethodKind kind) {
  for (const ConfigResult& c : shape.configs) {
    if (c.config.kind == kind && c.limitation.empty()) return "none";
  }
  return "cannot";
}

void printMatched(std::FILE* out, const std::vector<ShapeResult>& shapes) {
  for (const char* mode : kModes) {
    std::fprintf(
        out,
        "\nMatched error: fastest MIBIT against fastest mesh, and Embree's fastest cone and round curves, with "
        "max error <= level (%s; Mrays/s)\n",
        modeTitle(mode));
    std::fprintf(out, "%-8s %7s | %-14s %8s | %-16s %8s | %7s | %10s | %-16s %8s | %-23s %8s\n", "shape", "level",
                 "MIBIT", "Mrays/s", "mesh", "Mrays/s", "ratio", "mem ratio", "embree cone", "Mrays/s",
                 "embree round curve", "Mrays/s");
    for (const ShapeResult& shape : shapes) {
      for (const MatchedRow& row : shape.matched) {
        if (row.mode != mode) continue;
        const auto label = [&](const std::optional<std::size_t>& i) {
          return i ? shape.configs[*i].config.label() : std::string("none");
        };
        const auto speed = [&](const std::optional<std::size_t>& i) {
          return i ? shape.configs[*i].speed.at(mode).median : NAN;
        };
        char ratio[16] = "-", memory[16] = "-";
        if (row.mibit && row.mesh) std::snprintf(ratio, sizeof ratio, "%.2fx", speed(row.mibit) / speed(row.mesh));
        if (row.leanestMibit && row.leanestMesh) {
          std::snprintf(memory, sizeof memory, "%.0fx",
                        shape.configs[*row.leanestMesh].totalBytes() / shape.configs[*row.leanestMibit].totalBytes());
        }
        const auto curve = [&](const std::optional<std::size_t>& i, MethodKind kind) {
          return i ? shape.configs[*i].config.label() : noPick(shape, kind);
        };
        std::fprintf(out, "%-8s %7.0e | %-14s %8.3g | %-16s %8.3g | %7s | %10s | %-16s %8.3g | %-23s %8.3g\n",
                     shape.name.c_str(), row.level, label(row.mibit).c_str(), speed(row.mibit), label(row.mesh).c_str(),
                     speed(row.mesh), ratio, memory, curve(row.embreeCone, MethodKind::embreeCone).c_str(),
                     speed(row.embreeCone), curve(row.embreeRoundCurve, MethodKind::embreeRoundCurve).c_str(),
                     speed(row.embreeRoundCurve));
      }
    }
  }
}

// The curves: the exact spline beside MIBIT on 256 sampled points, and the points each way of
// sampling needs for the same max error.
void printCurves(std::FILE* out, const std::vector<ShapeResult>& shapes) {
  std::fprintf(out, "\nExact spline against MIBIT at 256 points (Mrays/s, 1 thread; max error relative to the size)\n");
  std::fprintf(out, "%-8s %6s %9s | %9s %8s %8s | %9s %8s %8s | %7s %7s\n", "shape", "pieces", "fit err", "spline err",
               "inc 1", "cam 8", "mibit err", "inc 1", "cam 8", "inc", "cam 8");
  for (const ShapeResult& shape : shapes) {
    const ConfigResult* spline = nullptr;
    const ConfigResult* mibit = nullptr;
    for (const ConfigResult& c : shape.configs) {
      if (c.config.kind == MethodKind::spline) spline = &c;
      if (c.config.kind == MethodKind::mibit && c.config.shell == ShellKind::cylinder && !c.config.binary &&
          c.config.points == 256)
        mibit = &c;
    }
    if (spline == nullptr || mibit == nullptr) continue;
    const auto speed = [](const ConfigResult* c, const char* mode) {
      const auto it = c->speed.find(mode);
      return it == c->speed.end() ? NAN : it->second.median;
    };
    std::fprintf(out, "%-8s %6zu %9.1e | %9.2e %8.3g %8.3g | %9.2e %8.3g %8.3g | %6.0f%% %6.0f%%\n", shape.name.c_str(),
                 shape.splinePieces, shape.splineError, spline->incoherent ? spline->incoherent->residualMax : NAN,
                 speed(spline, kIncoherent1), speed(spline, kCamera8),
                 mibit->incoherent ? mibit->incoherent->residualMax : NAN, speed(mibit, kIncoherent1),
                 speed(mibit, kCamera8), 100 * speed(spline, kIncoherent1) / speed(mibit, kIncoherent1),
                 100 * speed(spline, kCamera8) / speed(mibit, kCamera8));
  }
  std::fprintf(out,
               "\nPolyline points for one max error (closed forms): one sagitta for every arc (MIBIT's ladder), "
               "Profile::fromCurve of the spline, even spacing along the curve\n");
  std::fprintf(out, "%-8s %10s | %8s %9s %8s | %9s\n", "shape", "max error", "sagitta", "adaptive", "even",
               "adaptive/even");
  for (const ShapeResult& shape : shapes) {
    for (const PointsRow& row : shape.points) {
      std::fprintf(out, "%-8s %10.2e | %8d %9d %8d | %9.2f\n", shape.name.c_str(), row.error, row.samplePoints,
                   row.adaptivePoints, row.uniformPoints, double(row.adaptivePoints) / row.uniformPoints);
    }
  }
}

void printScaling(std::FILE* out, const ShapeResult& shape) {
  std::fprintf(out, "\n== scaling: %s, %zu incoherent rays, rtcIntersect1, 1 thread (Mrays/s; max error)\n",
               shape.name.c_str(), shape.incoherentRays);
  std::fprintf(out, "%-26s %10s %10s %12s\n", "method", "Mrays/s", "err max", "memory");
  for (const ConfigResult& c : shape.configs) {
    if (!c.limitation.empty()) {
      std::fprintf(out, "%-26s cannot: %s\n", c.config.label().c_str(), c.limitation.c_str());
      continue;
    }
    std::fprintf(out, "%-26s %10.4g %10.2e %12s\n", c.config.label().c_str(), c.speed.at(kIncoherent1).median,
                 c.incoherent ? c.incoherent->residualMax : NAN, bytesText(c.totalBytes()).c_str());
  }
}

// A CSV field: quoted when it holds a comma, a quote or a line break, quotes doubled (RFC 4180).
std::string csvText(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string csvNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

}  // namespace

void printTables(std::FILE* out, const RunResults& results) {
  for (const ShapeResult& shape : results.speedError) printShape(out, shape);
  if (!results.speedError.empty()) printMatched(out, results.speedError);
  if (!results.speedError.empty()) printCurves(out, results.speedError);
  for (const ShapeResult& shape : results.scaling) printScaling(out, shape);
}

void writeJson(io::OutputSet& outputs, const std::string& path, const RunResults& results,
               const std::string& commandLine) {
  json speedError = json::array(), scaling = json::array();
  for (const ShapeResult& shape : results.speedError) speedError.push_back(shapeJson(shape));
  for (const ShapeResult& shape : results.scaling) scaling.push_back(shapeJson(shape));
  const RunSettings& s = results.settings;
  const json document = {{"command", commandLine},
                         {"date", today()},
                         {"machine", {{"cpu", cpuModel()}, {"threads", std::thread::hardware_concurrency()}}},
                         {"embree", RTC_VERSION_STRING},
                         {"settings",
                          {{"quick", s.quick},
                           {"incoherent_rays", s.incoherentRays},
                           {"camera_width", s.cameraWidth},
                           {"camera_height", s.cameraHeight},
                           {"repetitions", s.repetitions},
                           {"min_seconds", s.minSeconds},
                           {"seed", s.seed}}},
                         {"speed_error", speedError},
                         {"scaling", scaling}};
  const std::string text = document.dump(1) + "\n";
  outputs.stream(path).write(text);
}

void writeCsv(io::OutputSet& outputs, const std::string& path, const RunResults& results) {
  std::ostringstream csv;
  csv << "suite,shape,method,points,slices,mode,mrays_median,mrays_low,mrays_high,residual_max,residual_p99,"
         "residual_rms,normal_p99_degrees,disagreement_fraction,other_sheet_fraction,revolve_bytes,embree_bytes,build_"
         "seconds,"
         "limitation\n";
  const auto rows = [&](const char* suite, const std::vector<ShapeResult>& shapes) {
    for (const ShapeResult& shape : shapes) {
      for (const ConfigResult& c : shape.configs) {
        if (!c.limitation.empty()) {  // one row, with the reason and no figures
          csv << suite << ',' << shape.name << ',' << c.config.method() << ',' << c.config.points << ','
              << c.config.slices << std::string(14, ',') << csvText(c.limitation) << '\n';
          continue;
        }
        for (const auto& [mode, t] : c.speed) {
          const std::optional<ErrorSummary>& e = mode.rfind("camera", 0) == 0 ? c.camera : c.incoherent;
          csv << suite << ',' << shape.name << ',' << c.config.method() << ',' << c.config.points << ','
              << c.config.slices << ',' << mode << ',' << csvNumber(t.median) << ',' << csvNumber(t.low) << ','
              << csvNumber(t.high) << ',';
          if (e) {
            csv << csvNumber(e->residualMax) << ',' << csvNumber(e->residualP99) << ',' << csvNumber(e->residualRms)
                << ',' << csvNumber(e->normalP99Degrees) << ',' << csvNumber(e->disagreementFraction()) << ','
                << csvNumber(e->otherSheetFraction());
          } else {
            csv << ",,,,,";
          }
          csv << ',' << c.revolveBytes << ',' << c.embreeBytes << ',' << csvNumber(c.buildSeconds) << ",\n";
        }
      }
    }
  };
  rows("speed_error", results.speedError);
  rows("scaling", results.scaling);
  const std::string text = csv.str();
  outputs.stream(path).write(text);
}

}  // namespace revolve::bench
