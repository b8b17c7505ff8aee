// revolve-bench --quick as CI runs it: it asserts nothing about speed (a timed test would only
// measure the machine), only that every figure the benchmark promises is produced, and finite.
#include "io/scratch_directory.h"
#include "support/process.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <map>
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
    for (std::size_t i = 0; i < value.size(); ++i)
      expectFinite(value[i], path + "[" + std::to_string(i) + "]", nullable);
  }
}

TEST(RevolveBenchTest, QuickRunProducesEveryFigure) {
  const ScratchDirectory scratch;
  const std::string jsonPath = scratch / "bench.json", csvPath = scratch / "bench.csv";
  const auto run = runProcess(REVOLVE_BENCH_PATH, {"--quick", "--json", jsonPath, "--csv", csvPath});
  ASSERT_EQ(run.status, 0) << run.err;
  const json document = json::parse(revolve::testing::readWholeFile(jsonPath));
  // Errors are absent for the analytic sphere on shapes it is not and for configurations a method
  // cannot trace (with their limitation); a matched pick is absent where no configuration of the
  // quick ladders reaches the level.
  expectFinite(document, "",
               {"error_incoherent", "error_camera", "mibit", "mesh", "leanest_mibit", "leanest_mesh", "embree_cone",
                "embree_round_curve", "limitation"});

  const std::set<std::string> timedEverywhere = {"mibit", "mesh", "sphere", "embree_cone", "embree_round_curve",
                                                 "spline"};
  const std::set<std::string> modes = {"incoherent_1",   "camera_1",   "camera_8",
                                       "incoherent_all", "occluded_1", "occluded_8"};
  ASSERT_EQ(document["speed_error"].size(), 5u);
  // Embree's curves take these shapes (the cone curve: some resolutions) and refuse the others,
  // whose flat rings neither can express (see tests/embree_cone_test.cpp and bench/round_curve.h).
  const std::set<std::string> coneTakes = {"sphere", "vase"}, roundTakes = {"sphere", "torus", "vase"};
  for (const json& shape : document["speed_error"]) {
    const std::string name = shape["shape"];
    std::set<std::string> methods;
    std::map<std::string, int> traced;
    for (const json& config : shape["configs"]) {
      const std::string method = config["method"];
      methods.insert(method);
      const json& speed = config["mrays_per_second"];
      if (!config["limitation"].is_null()) {
        // Refused: a reason, and no figure that could be mistaken for a measurement.
        EXPECT_FALSE(config["limitation"].get<std::string>().empty()) << name << " " << config["label"];
        EXPECT_TRUE(speed.empty()) << name << " " << config["label"];
        EXPECT_TRUE(config["error_incoherent"].is_null() && config["error_camera"].is_null())
            << name << " " << config["label"];
        continue;
      }
      ++traced[method];
      // Every method but the analytic sphere has a resolution, which the tables and plots print.
      if (method != "sphere") {
        EXPECT_GT(config["points"].get<int>(), 0) << name << " " << config["label"];
      }
      EXPECT_TRUE(speed.contains("incoherent_1")) << name << " " << config["label"];
      if (timedEverywhere.count(method) == 1) {
        for (const std::string& mode : modes)
          EXPECT_TRUE(speed.contains(mode)) << name << " " << config["label"] << " " << mode;
      }
      for (const auto& [mode, figures] : speed.items())
        EXPECT_GT(figures["median"].get<double>(), 0.0) << name << " " << mode;
      if (method != "sphere" || name == "sphere") {
        for (const char* rays : {"error_incoherent", "error_camera"}) {
          ASSERT_TRUE(config[rays].is_object()) << name << " " << config["label"] << " " << rays;
          EXPECT_GT(config[rays]["hits"].get<int>(), 0) << name << " " << config["label"];
          EXPECT_GE(config[rays]["residual_max"].get<double>(), config[rays]["residual_p99"].get<double>());
          EXPECT_LE(config[rays]["other_sheet"].get<int>(), config[rays]["both_hit"].get<int>());
        }
      }
      EXPECT_GT(config["total_bytes"].get<double>(), 0.0);
    }
    EXPECT_EQ(methods, (std::set<std::string>{"sphere", "mibit", "mibit_binary", "mibit_cone", "mibit_hybrid", "linear",
                                              "kajiya", "mesh", "embree_cone", "embree_round_curve", "spline",
                                              "adaptive", "uniform", "mesh_adaptive"}))
        << name;
    EXPECT_EQ(traced["embree_cone"] > 0, coneTakes.count(name) == 1) << name;
    EXPECT_EQ(traced["embree_round_curve"] > 0, roundTakes.count(name) == 1) << name;
    // The spline fits the profile within 1e-9 of its size (closed form), and tracing it exactly
    // leaves the float hit points' rounding: every hit within 1e-6 of the size of the true surface.
    EXPECT_LE(shape["spline_error"].get<double>(), 1e-9) << name;
    EXPECT_GT(shape["spline_pieces"].get<int>(), 0) << name;
    for (const json& config : shape["configs"]) {
      if (config["method"] != "spline") continue;
      for (const char* rays : {"error_incoherent", "error_camera"})
        EXPECT_LE(config[rays]["residual_max"].get<double>(), 1e-6) << name;
    }
    // Polyline points for one error, each sampling's count (how they compare is what the run reports).
    for (const json& row : shape["polyline_points"]) {
      for (const char* key : {"sample_points", "adaptive_points", "uniform_points"})
        EXPECT_GT(row[key].get<int>(), 1) << name;
    }
    EXPECT_EQ(shape["matched"].size(), 24u) << name;  // four error levels in six timing modes
  }
  ASSERT_EQ(document["scaling"].size(), 1u);
  std::set<std::string> scaled;
  for (const json& config : document["scaling"][0]["configs"]) scaled.insert(config["method"].get<std::string>());
  EXPECT_EQ(scaled, (std::set<std::string>{"mibit", "mibit_binary", "linear", "kajiya", "mesh", "embree_cone",
                                           "embree_round_curve"}));

  const std::string csv = revolve::testing::readWholeFile(csvPath);
  EXPECT_EQ(csv.rfind("suite,shape,method,points,slices,mode,mrays_median", 0), 0u);
  // A refused configuration is one row with its reason, quoted (the reasons hold commas).
  EXPECT_NE(csv.find("speed_error,goblet,embree_cone,16,0,,,,,,,,,,,,,,\"the segment from profile point"),
            std::string::npos);
  EXPECT_GT(std::count(csv.begin(), csv.end(), '\n'), 100);
}

TEST(RevolveBenchTest, QuickPaperTableProducesEveryFigure) {
  const ScratchDirectory scratch;
  const std::string jsonPath = scratch / "paper.json";
  const auto run = runProcess(REVOLVE_BENCH_PATH, {"paper-table", "--quick", "--scene",
                                                   REVOLVE_SOURCE_DIR "/scenes/patio.json", "--json", jsonPath});
  ASSERT_EQ(run.status, 0) << run.err;
  const json document = json::parse(revolve::testing::readWholeFile(jsonPath));
  // The paper's own figures are null where its table (as our copy has it) has none.
  expectFinite(document, "", {"improved_percent", "nodes_percent", "shell_millions", "quadratic_millions"});
  for (const char* key : {"command", "date", "machine", "settings"}) EXPECT_TRUE(document.contains(key)) << key;
  EXPECT_EQ(document["settings"]["threads"], 1);
  ASSERT_EQ(document["examples"].size(), 2u);
  std::set<int> tables;
  for (const json& example : document["examples"]) {
    tables.insert(example["paper"]["table"].get<int>());
    // KJ, the three shells x monotone split x range search, the wide tree.
    ASSERT_EQ(example["rows"].size(), 14u);
    std::set<std::string> variants;
    for (const json& row : example["rows"]) {
      const std::string label = row["row"];
      variants.insert(label + (row["monotone_split"].get<bool>() ? "+MI" : "") +
                      (row["range_search"].get<bool>() ? "+RS" : ""));
      for (const char* figure : {"total_seconds", "mrays_per_second", "shell_tests_millions", "quadratics_millions",
                                 "nodes_traversed_percent", "speedup_over_kj"}) {
        EXPECT_GT(row[figure].get<double>(), 0.0) << label << " " << figure;
      }
      EXPECT_GT(row["render_seconds"]["median"].get<double>(), 0.0) << label;
      EXPECT_GT(row["counters"]["tree_nodes"].get<double>(), 0.0) << label;
      EXPECT_EQ(row["rays"]["camera"], 24 * 24) << label;
      EXPECT_TRUE(row["same_image_as_kj"].get<bool>()) << label << ": every row traces the same rays to the same hits";
    }
    EXPECT_EQ(variants.size(), 14u);
    EXPECT_FALSE(example["paper"]["rows"].empty());
  }
  EXPECT_EQ(tables, (std::set<int>{2, 4}));
  EXPECT_NE(run.out.find("Table 4"), std::string::npos) << "the paper's figures are printed beside ours";
}

TEST(RevolveBenchTest, PovComparisonSaysSoAndSucceedsWhenPovrayIsAbsent) {
  // The POV-Ray runs are documented commands, not CI steps: without povray on PATH they skip.
  const std::string saved = std::getenv("PATH") != nullptr ? std::getenv("PATH") : "";
  const ScratchDirectory scratch;
  setenv("PATH", scratch.path().c_str(), 1);
  const auto run = runProcess(
      REVOLVE_BENCH_PATH, {"pov", "--scene", REVOLVE_SOURCE_DIR "/scenes/patio_points.json", "--out", scratch / "out"});
  const auto scaling = runProcess(REVOLVE_BENCH_PATH, {"pov-scaling", "--out", scratch / "out"});
  setenv("PATH", saved.c_str(), 1);
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(run.err,
            "revolve-bench: skipped: povray is not installed (Debian: apt-get install povray, or "
            "scripts/install-deps.sh --test)\n");
  EXPECT_EQ(scaling.status, 0) << scaling.err;
  EXPECT_EQ(scaling.err, run.err);
  EXPECT_TRUE(scratch.entries().empty());
}

TEST(RevolveBenchTest, BadCameraSizeIsAnErrorAndWritesNothing) {
  const ScratchDirectory scratch;
  const std::string jsonPath = scratch / "bench.json";
  const auto run = runProcess(REVOLVE_BENCH_PATH, {"--quick", "--camera", "30x7", "--json", jsonPath});
  EXPECT_EQ(run.status, 1);
  EXPECT_EQ(run.err,
            "revolve-bench: --camera 30x7: expected WIDTHxHEIGHT, width a positive multiple of 4, height of 2\n");
  EXPECT_TRUE(scratch.entries().empty());
}

TEST(RevolveBenchTest, ScaleReportsEveryFigureAndMeshesMatchTheExactSurfaces) {
  // The same 60 objects, exact and meshed at matched error (a 64-point polyline's own error, about
  // 2e-3 of an object): the same rays hit the same objects but where the meshes' facets cut a
  // silhouette, a thin band, so the hit counts agree within 2%.
  const ScratchDirectory scratch;
  std::map<std::string, json> runs;
  for (const std::string geometry : {"revolve", "mesh"}) {
    const std::string jsonPath = scratch / (geometry + ".json");
    const auto run = runProcess(REVOLVE_BENCH_PATH, {"scale", "--quick", "--objects", "60", "--geometry", geometry,
                                                     "--lidar", "256", "--json", jsonPath});
    ASSERT_EQ(run.status, 0) << run.err;
    runs[geometry] = json::parse(revolve::testing::readWholeFile(jsonPath));
    const json& document = runs[geometry];
    expectFinite(document, "", {});
    EXPECT_EQ(document["objects"], 60);
    EXPECT_EQ(document["refused_rays"], 0);
    EXPECT_GT(document["build_seconds"].get<double>(), 0.0);
    EXPECT_GE(document["first_ray_seconds"].get<double>(), document["build_seconds"].get<double>());
    EXPECT_GT(document["memory"]["peak_resident_bytes"].get<double>(), 0.0);
    EXPECT_GT(document["camera"]["hits"].get<double>(), 0.1 * document["camera"]["rays"].get<double>());
  }
  const json& exact = runs["revolve"];
  // The breakdown adds up to the shape's own count.
  for (const char* kind : {"polyline", "spline"}) {
    const json& parts = exact["shape_bytes"][kind];
    double sum = 0;
    for (const char* part : {"shape_struct", "profile_points", "profile_arc_lengths", "profile_source_indices",
                             "mibit_tree", "wide_tree", "curve_parts", "arc_tables", "spline"})
      sum += parts[part].get<double>();
    EXPECT_EQ(sum, parts["total"].get<double>()) << kind;
  }
  for (const char* rays : {"camera", "lidar"}) {
    const double a = exact[rays]["hits"].get<double>(), b = runs["mesh"][rays]["hits"].get<double>();
    EXPECT_LE(std::abs(a - b), 0.02 * a) << rays << ": " << a << " exact hits, " << b << " on meshes";
  }
}

TEST(RevolveBenchTest, ScaleBuiltByTheLibraryAloneHitsAsTheSceneStack) {
  // The same 60 objects built by the library alone (no description, no scene records) and through
  // the scene stack. The stack places each object by its linear map rounded to float, the library
  // build by the map in double: silhouettes differ by about 1e-7 of an object, which a ray of
  // these grids (pixels about 1e-2 of an object apart) meets with odds far below one in the run;
  // so the counts agree, give or take one ray for bad luck.
  const ScratchDirectory scratch;
  std::map<std::string, json> runs;
  for (const std::string build : {"scene", "library"}) {
    const std::string jsonPath = scratch / (build + ".json");
    const auto run = runProcess(REVOLVE_BENCH_PATH, {"scale", "--quick", "--objects", "60", "--build", build, "--lidar",
                                                     "256", "--json", jsonPath});
    ASSERT_EQ(run.status, 0) << run.err;
    runs[build] = json::parse(revolve::testing::readWholeFile(jsonPath));
    const json& document = runs[build];
    expectFinite(document, "", {});
    EXPECT_EQ(document["build"], build);
    EXPECT_EQ(document["objects"], 60);
    EXPECT_GT(document["build_seconds"].get<double>(), 0.0);
    EXPECT_GT(document["memory"]["revolve_bytes"].get<double>(), 0.0);
    EXPECT_GT(document["camera"]["hits"].get<double>(), 0.1 * document["camera"]["rays"].get<double>());
  }
  for (const char* rays : {"camera", "lidar"}) {
    const double a = runs["scene"][rays]["hits"].get<double>(), b = runs["library"][rays]["hits"].get<double>();
    EXPECT_LE(std::abs(a - b), 1.0) << rays << ": " << a << " through the scene stack, " << b << " by the library";
  }
  // The same shapes, so the same bytes: a Spline built in place holds no more than a copied one.
  EXPECT_EQ(runs["scene"]["shape_bytes"], runs["library"]["shape_bytes"]);
  // A mesh or a scene file is the scene stack's to build.
  const auto mesh =
      runProcess(REVOLVE_BENCH_PATH, {"scale", "--objects", "4", "--build", "library", "--geometry", "mesh"});
  EXPECT_EQ(mesh.status, 1);
  EXPECT_NE(mesh.err.find("--build library builds exact surfaces"), std::string::npos) << mesh.err;
}

}  // namespace
}  // namespace revolve::bench
