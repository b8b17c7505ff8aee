// revolve-bench paper-table: Baciu, Jia & Lam 2001's Tables 2 and 4 reproduced on the patio.
//
// The patio rendered by revolve-render's Whitted ray tracer (in process) at one sample a pixel,
// as the paper's Example 1 (ray casting: depth 1, no shadows) and Example 2 (depth 4, shadows),
// once per row: Kajiya's strip tree, the paper's binary MIBIT tree with cylinder, cone and hybrid
// shells with and without the monotone split and the range search, and the wide tree revolve uses
// by default. Every row traces the same rays (the images agree bit for bit). Times are medians of
// interleaved repetitions with counting off; the counters come from one more render with it on.
#pragma once

#include "paper_figures.h"

#include <nlohmann/json.hpp>

#include <revolve/baselines.h>
#include <revolve/revolve.h>

#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace revolve::bench {

struct PaperTableSettings {
  std::string scene = "scenes/patio.json";
  int size = 300;        // the image is size x size, as the paper's
  int threads = 1;       // the paper's Pentium III had one
  int repetitions = 11;  // the patio renders in milliseconds: many, for the median
};

struct PaperTableRow {
  std::string label;  // "KJ", "CY", "TC", "HY", "wide"
  BuildOptions options;
  double buildSeconds = 0;
  double renderSeconds = 0, renderLow = 0, renderHigh = 0;  // median and range of the repetitions
  std::uint64_t cameraRays = 0, bounceRays = 0, shadowRays = 0;
  Stats counters;             // summed over the counting render
  std::size_t treeNodes = 0;  // summed over the scene's objects
  bool sameImage = true;      // bit for bit the first row's image
  double totalSeconds() const { return buildSeconds + renderSeconds; }
  std::uint64_t rays() const { return cameraRays + bounceRays + shadowRays; }
};

struct PaperExample {
  std::string name;  // "Example 1", "Example 2"
  int depth = 1;
  bool shadows = false;
  PaperTable paper;
  std::vector<PaperTableRow> rows;
};

// Both examples, every row. Throws on a bad scene.
std::vector<PaperExample> runPaperTable(const PaperTableSettings& settings);

void printPaperTable(std::FILE* out, const PaperTableSettings& settings, const std::vector<PaperExample>& examples);
nlohmann::ordered_json paperTableJson(const PaperTableSettings& settings, const std::vector<PaperExample>& examples);

}  // namespace revolve::bench
