// revolve-bench --quick as CI runs it: it asserts nothing about speed (a timed test would only
// measure the machine), only that every figure the benchmark promises is produced, and finite.
#include "io/scratch_directory.h"
#include "support/process.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

namespace revolve::bench {
namespace {

using nlohmann::json;
using revolve::testing::runProcess;
using revolve::testing::ScratchDirectory;

// Every number in the document is finite; nulls are allowed only under the keys listed.
void expectFinite(const json& value, const std::string& path, const std::set<std::string>& nullable) {
  if (value.is_number()) {
    EXPECT_TRUE(std::isfinite(value.get<double>())) << path;
  } else if (value.is_null()) {
    const std::string key = path.substr(path.rfind('.') + 1);
    EXPECT_TRUE(nullable.count(key) == 1) << path << " is null";
  } else if (value.is_object()) {
    for (const auto& [key, child] : value.items()) expectFinite(child, path + "." + key, nullable);
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i) expectFinite(value[i], path + "[" + std::to_string(i) + "]", nullable);
  }
}

TEST(RevolveBenchTest, QuickRunProducesEveryFigure) {
  const ScratchDirectory scratch;
  const std::string jsonPath = scratch / "bench.json", csvPath = scratch / "bench.csv";
  const auto run = runProcess(REVOLVE_BENCH_PATH, {"--quick", "--json", jsonPath, "--csv", csvPath});
  ASSERT_EQ(run.status, 0) << run.err;
  const json document = json::parse(revolve::testing::readWholeFile(jsonPath));
  // Errors are absent for the analytic sphere on shapes it is not; a matched pick is absent where
  // no configuration of the quick ladders reaches the level.
  expectFinite(document, "", {"error_incoherent", "error_camera", "mibit", "mesh", "leanest_mibit", "leanest_mesh"});

  const std::set<std::string> timedEverywhere = {"mibit", "mesh", "sphere", "spline"};
  const std::set<std::string> modes = {"incoherent_1", "camera_1", "camera_8", "incoherent_all"};
  ASSERT_EQ(document["speed_error"].size(), 5u);
  for (const json& shape : document["speed_error"]) {
    const std::string name = shape["shape"];
    std::set<std::string> methods;
    for (const json& config : shape["configs"]) {
      const std::string method = config["method"];
      methods.insert(method);
      const json& speed = config["mrays_per_second"];
      EXPECT_TRUE(speed.contains("incoherent_1")) << name << " " << config["label"];
      if (timedEverywhere.count(method) == 1) {
        for (const std::string& mode : modes) EXPECT_TRUE(speed.contains(mode)) << name << " " << config["label"] << " " << mode;
      }
      for (const auto& [mode, figures] : speed.items()) EXPECT_GT(figures["median"].get<double>(), 0.0) << name << " " << mode;
      if (method != "sphere" || name == "sphere") {
        for (const char* rays : {"error_incoherent", "error_camera"}) {
          ASSERT_TRUE(config[rays].is_object()) << name << " " << config["label"] << " " << rays;
          EXPECT_GT(config[rays]["hits"].get<int>(), 0) << name << " " << config["label"];
          EXPECT_GE(config[rays]["residual_max"].get<double>(), config[rays]["residual_p99"].get<double>());
        }
      }
      EXPECT_GT(config["total_bytes"].get<double>(), 0.0);
    }
    EXPECT_EQ(methods, (std::set<std::string>{"sphere", "mibit", "mibit_binary", "mibit_cone", "mibit_hybrid", "linear",
                                               "kajiya", "mesh", "spline", "adaptive", "uniform", "mesh_adaptive"}))
        << name;
    // The spline fits the profile within 1e-9 of its size (closed form), and tracing it exactly
    // leaves the float hit points' rounding: every hit within 1e-6 of the size of the true surface.
    EXPECT_LE(shape["spline_error"].get<double>(), 1e-9) << name;
    EXPECT_GT(shape["spline_pieces"].get<int>(), 0) << name;
    for (const json& config : shape["configs"]) {
      if (config["method"] != "spline") continue;
      for (const char* rays : {"error_incoherent", "error_camera"}) EXPECT_LE(config[rays]["residual_max"].get<double>(), 1e-6) << name;
    }
    // Polyline points for one error, each sampling's count (how they compare is what the run reports).
    for (const json& row : shape["polyline_points"]) {
      for (const char* key : {"sample_points", "adaptive_points", "uniform_points"}) EXPECT_GT(row[key].get<int>(), 1) << name;
    }
    EXPECT_EQ(shape["matched"].size(), 16u) << name;  // four error levels in four timing modes
  }
  ASSERT_EQ(document["scaling"].size(), 1u);
  std::set<std::string> scaled;
  for (const json& config : document["scaling"][0]["configs"]) scaled.insert(config["method"].get<std::string>());
  EXPECT_EQ(scaled, (std::set<std::string>{"mibit", "mibit_binary", "linear", "kajiya", "mesh"}));

  const std::string csv = revolve::testing::readWholeFile(csvPath);
  EXPECT_EQ(csv.rfind("suite,shape,method,points,slices,mode,mrays_median", 0), 0u);
  EXPECT_GT(std::count(csv.begin(), csv.end(), '\n'), 100);
}

TEST(RevolveBenchTest, BadCameraSizeIsAnErrorAndWritesNothing) {
  const ScratchDirectory scratch;
  const std::string jsonPath = scratch / "bench.json";
  const auto run = runProcess(REVOLVE_BENCH_PATH, {"--quick", "--camera", "30x7", "--json", jsonPath});
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("--camera 30x7"), std::string::npos) << run.err;
  EXPECT_TRUE(scratch.entries().empty());
}

}  // namespace
}  // namespace revolve::bench
