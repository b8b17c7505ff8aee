// revolve-embree-answers: what Embree reports for the benchmark's rays, written out so that builds
// against different Embrees (3.13 on Debian 12, 4.x on Debian 13) can be compared.
//
//   revolve-embree-answers write OUT.csv [--rays N]
//   revolve-embree-answers compare A.csv B.csv
//
// `write` traces the benchmark's seeded incoherent rays (rtcIntersect1 and rtcOccluded1) and camera
// rays (rtcIntersect8) at each test shape, through revolve's geometry (MIBIT on 64- and 1,024-point
// polylines, the spline exactly) and through Embree's own primitives on the same polylines (a
// 64 x 64 mesh, the linear cone curve), one line per ray with every float as a hexadecimal literal.
// `compare` reads two such files: revolve's answers must agree bit for bit (hit or miss, t, Ng,
// primID, u, v, and occlusion); Embree's own primitives are Embree's kernels, which Embree 4 changed,
// so their differences are counted and measured, not refused. Exit status 1 when revolve's differ.
#include <revolve/embree_baselines.h>
#include "ray_sets.h"
#include "smooth_spline.h"
#include "test_shapes.h"
#include "traced_scene.h"

#include "cli/command_line.h"
#include "embree/embree_handles.h"
#include "embree/embree_rays.h"
#include "io/output_set.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace revolve;
using namespace revolve::bench;

constexpr int kCameraSide = 32;            // camera rays: 32 x 32, in packets of 8
constexpr std::uint64_t kSeed = 20011001;  // the incoherent rays' seed
constexpr double kSplineError = 1e-9;      // the spline's distance from the profile, relative
const char* const kHeader = "shape,method,query,ray,hit,t,ng_x,ng_y,ng_z,prim,u,v";

// The methods whose answers are revolve's own (compared bit for bit) and Embree's (measured).
std::vector<MethodConfig> methods() {
  return {{.kind = MethodKind::mibit, .shell = ShellKind::cylinder, .points = 64},
          {.kind = MethodKind::mibit, .shell = ShellKind::cylinder, .points = 1024},
          {.kind = MethodKind::spline},
          {.kind = MethodKind::mesh, .shell = ShellKind::cylinder, .points = 64, .slices = 64},
          {.kind = MethodKind::embreeCone, .shell = ShellKind::cylinder, .points = 64}};
}
bool revolvesOwn(const std::string& method) { return method.rfind("mibit", 0) == 0 || method.rfind("spline", 0) == 0; }

void writeHit(std::FILE* out, const std::string& prefix, std::size_t index, const RTCRayHit& rh) {
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
    std::fprintf(out, "%s,%zu,0,,,,,,,\n", prefix.c_str(), index);
    return;
  }
  std::fprintf(out, "%s,%zu,1,%a,%a,%a,%a,%u,%a,%a\n", prefix.c_str(), index, double(rh.ray.tfar), double(rh.hit.Ng_x),
               double(rh.hit.Ng_y), double(rh.hit.Ng_z), rh.hit.primID, double(rh.hit.u), double(rh.hit.v));
}

void writeShape(std::FILE* out, RTCDevice device, const MemoryMonitor& monitor, const SmoothProfile& profile,
                std::size_t rays) {
  const SmoothProfile::Extent e = profile.extent();
  const Box box{{-e.rMax, -e.rMax, e.zLow}, {e.rMax, e.rMax, e.zHigh}};
  const std::vector<Ray> incoherent = incoherentRays(box, rays, kSeed);
  const std::vector<Ray> camera = cameraRays(box, kCameraSide, kCameraSide);
  const Spline spline(SplineKind::bezier, bezierOf(profile, kSplineError * profile.size()).bezier);
  const AnalyticSphere unused{{0, 0, 0}, 1};
  for (const MethodConfig& config : methods()) {
    if (limitationOf(profile, config)) continue;  // Embree's cone curve cannot trace every profile
    const TracedScene traced(device, monitor, profile, spline, config, unused);
    const std::string prefix = profile.name() + "," + config.label();
    embree::RayQuery query;
    for (std::size_t i = 0; i < incoherent.size(); ++i) {
      RTCRayHit rh = app::embreeRayHit(incoherent[i]);
      query.intersect(traced.scene(), rh);
      writeHit(out, prefix + ",intersect1", i, rh);
      RTCRay shadow = app::embreeRayHit(incoherent[i]).ray;
      query.occluded(traced.scene(), shadow);
      std::fprintf(out, "%s,occluded1,%zu,%d,,,,,,,\n", prefix.c_str(), i, shadow.tfar < 0.0f ? 1 : 0);
    }
    alignas(32) const int valid[8] = {-1, -1, -1, -1, -1, -1, -1, -1};
    for (std::size_t first = 0; first < camera.size(); first += 8) {
      alignas(32) RTCRayHit8 packet{};
      for (int lane = 0; lane < 8; ++lane) {
        const RTCRayHit one = app::embreeRayHit(camera[first + lane]);
        packet.ray.org_x[lane] = one.ray.org_x, packet.ray.org_y[lane] = one.ray.org_y,
        packet.ray.org_z[lane] = one.ray.org_z;
        packet.ray.dir_x[lane] = one.ray.dir_x, packet.ray.dir_y[lane] = one.ray.dir_y,
        packet.ray.dir_z[lane] = one.ray.dir_z;
        packet.ray.tnear[lane] = one.ray.tnear, packet.ray.tfar[lane] = one.ray.tfar,
        packet.ray.mask[lane] = one.ray.mask;
        packet.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
      }
      query.intersect(valid, traced.scene(), packet);
      for (int lane = 0; lane < 8; ++lane) {
        RTCRayHit rh{};
        rh.ray.tfar = packet.ray.tfar[lane];
        rh.hit.geomID = packet.hit.geomID[lane];
        rh.hit.Ng_x = packet.hit.Ng_x[lane], rh.hit.Ng_y = packet.hit.Ng_y[lane], rh.hit.Ng_z = packet.hit.Ng_z[lane];
        rh.hit.primID = packet.hit.primID[lane], rh.hit.u = packet.hit.u[lane], rh.hit.v = packet.hit.v[lane];
        writeHit(out, prefix + ",intersect8", first + lane, rh);
      }
    }
  }
}

// One answer as written: everything after the ray's index, and t for measuring differences.
struct Answer {
  std::string fields;
  double t = std::numeric_limits<double>::quiet_NaN();
  bool hit = false;
};

// Reads a file written by `write`: key (shape, method, query, ray) to answer. Lines are bounded
// (the writer's are under 200 characters).
std::map<std::string, Answer> readAnswers(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot be opened");
  std::map<std::string, Answer> answers;
  std::string line;
  std::size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.size() > 400)
      throw std::runtime_error(path + ":" + std::to_string(number) + ": a line longer than 400 characters");
    if (number == 1) {
      if (line != kHeader)
        throw std::runtime_error(path + ":1: not a revolve-embree-answers file (expected the header " + kHeader + ")");
      continue;
    }
    if (std::count(line.begin(), line.end(), ',') != 11) {
      throw std::runtime_error(path + ":" + std::to_string(number) + ": not 12 comma-separated fields (" + kHeader +
                               ")");
    }
    std::size_t comma = 0;
    for (int i = 0; i < 4; ++i) comma = line.find(',', comma + (i > 0));
    Answer answer;
    answer.fields = line.substr(comma + 1);
    answer.hit = answer.fields.rfind("1", 0) == 0;
    const std::size_t tAt = answer.fields.find(',');
    if (answer.hit && tAt != std::string::npos) answer.t = std::strtod(answer.fields.c_str() + tAt + 1, nullptr);
    answers.emplace(line.substr(0, comma), std::move(answer));
  }
  if (number <= 1) throw std::runtime_error(path + ": no answers");
  return answers;
}

int compare(const std::string& pathA, const std::string& pathB) {
  const std::map<std::string, Answer> a = readAnswers(pathA), b = readAnswers(pathB);
  struct Tally {
    std::size_t rays = 0, hitMiss = 0, differing = 0;
    double maxRelativeT = 0;
  };
  std::map<std::string, Tally> tallies;  // by shape, method and query
  std::size_t missing = 0;
  for (const auto& [key, answerA] : a) {
    const std::string group = key.substr(0, key.rfind(','));
    Tally& tally = tallies[group];
    ++tally.rays;
    const auto found = b.find(key);
    if (found == b.end()) {
      ++missing;
      continue;
    }
    const Answer& answerB = found->second;
    if (answerA.hit != answerB.hit) ++tally.hitMiss;
    if (answerA.fields != answerB.fields) ++tally.differing;
    if (answerA.hit && answerB.hit) {
      tally.maxRelativeT =
          std::max(tally.maxRelativeT, std::abs(answerA.t - answerB.t) / std::max(1.0, std::abs(answerA.t)));
    }
  }
  missing += b.size() > a.size() ? b.size() - a.size() : 0;
  bool revolveDiffers = missing > 0;
  std::printf("%-44s %7s %9s %9s %12s\n", "shape, method, query", "rays", "hit/miss", "differ", "max |dt|/t");
  for (const auto& [group, tally] : tallies) {
    const std::string method = group.substr(group.find(',') + 1);
    const bool own = revolvesOwn(method);
    revolveDiffers = revolveDiffers || (own && tally.differing > 0);
    std::printf("%-44s %7zu %9zu %9zu %12.3g%s\n", group.c_str(), tally.rays, tally.hitMiss, tally.differing,
                tally.maxRelativeT, own ? "" : "  (Embree's own kernel)");
  }
  if (missing > 0) std::printf("%zu rays are in one file and not the other\n", missing);
  std::printf("%s\n", revolveDiffers ? "revolve's answers DIFFER between the two builds"
                                     : "revolve's answers are the same bit for bit in both builds");
  return revolveDiffers ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{"What Embree reports for the benchmark's rays, to compare builds against different Embrees"};
  std::string out, a, b;
  std::size_t rays = 4000;
  CLI::App* write = cli.add_subcommand("write", "trace the rays and write every answer to OUT.csv");
  write->add_option("out", out, "the CSV to write")->required()->check(app::kNonEmpty);
  write->add_option("--rays", rays, "incoherent rays a shape (default 4,000)")
      ->check(app::wholeNumberIn<std::size_t>(1, 1000000));
  CLI::App* comparison =
      cli.add_subcommand("compare", "compare two written files; status 1 when revolve's answers differ");
  comparison->add_option("a", a, "a CSV from one build")->required()->check(CLI::ExistingFile);
  comparison->add_option("b", b, "a CSV from the other build")->required()->check(CLI::ExistingFile);
  cli.require_subcommand(1);
  if (const std::optional<int> status = app::parseCommandLine(cli, argc, argv, "revolve-embree-answers"))
    return *status;

  if (comparison->parsed()) {
    int status = 1;
    const int failed = app::runTool("revolve-embree-answers", a + " and " + b, [&] { status = compare(a, b); });
    return failed != 0 ? failed : status;
  }
  return app::runTool("revolve-embree-answers", out, [&] {
    io::OutputSet outputs;
    outputs.add("OUT", out);
    const app::Device device = app::newDevice();
    const MemoryMonitor monitor(device.get());
    outputs.write(out, [&](std::FILE* file) {
      std::fprintf(file, "%s\n", kHeader);
      for (const SmoothProfile& profile : testShapes()) writeShape(file, device.get(), monitor, profile, rays);
    });
    outputs.commit();
    std::printf("wrote %s (Embree %d)\n", out.c_str(), embree::kMajorVersion);
  });
}
