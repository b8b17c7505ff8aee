#include "paper_table.h"

#include "io/scene_file.h"
#include "render/renderer.h"
#include "scene/embree_scene.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace revolve::bench {
namespace {

const char* shellLabel(ShellKind shell) {
  switch (shell) {
    case ShellKind::cylinder:
      return "CY";
    case ShellKind::cone:
      return "TC";
    case ShellKind::hybrid:
      return "HY";
  }
  return "?";
}

// KJ; the paper's binary tree with each shell, with the monotone split (the paper's Tables 2 and 4)
// and without it, each without and with the range search; and the wide tree revolve uses by default.
PaperTableRow tableRow(const std::string& label, const BuildOptions& options) {
  PaperTableRow row;
  row.label = label;
  row.options = options;
  return row;
}

std::vector<PaperTableRow> tableRows() {
  std::vector<PaperTableRow> rows;
  BuildOptions kajiya;
  kajiya.method = Method::kajiya;
  rows.push_back(tableRow("KJ", kajiya));
  for (const bool monotone : {true, false}) {
    for (const bool range : {false, true}) {
      for (const ShellKind shell : {ShellKind::cylinder, ShellKind::cone, ShellKind::hybrid}) {
        BuildOptions options;
        options.shell = shell;
        options.monotoneSplit = monotone;
        options.rangeSearch = range;
        options.wideNodes = false;
        rows.push_back(tableRow(shellLabel(shell), options));
      }
    }
  }
  rows.push_back(tableRow("wide", BuildOptions{}));
  return rows;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

render::RenderSettings renderSettings(const PaperTableSettings& settings, const PaperExample& example) {
  render::RenderSettings render;
  render.width = render.height = settings.size;
  render.spp = 1;
  render.threads = settings.threads;
  render.integrator.kind = render::IntegratorKind::whitted;
  render.integrator.depth = example.depth;
  render.integrator.shadows = example.shadows;
  return render;
}

void runExample(const io::SceneDescription& description, const PaperTableSettings& settings, PaperExample& example) {
  const render::RenderSettings render = renderSettings(settings, example);
  example.rows = tableRows();
  std::vector<std::unique_ptr<scene::EmbreeScene>> scenes;
  for (PaperTableRow& row : example.rows) {
    scenes.push_back(std::make_unique<scene::EmbreeScene>(description, scene::BuildSettings{.options = row.options}));
    row.buildSeconds = scenes.back()->buildSeconds();
  }
  // Repetitions interleaved, each starting at another row, so that a noisy moment of a shared
  // machine is spread over the rows instead of landing on one.
  std::vector<std::vector<double>> seconds(example.rows.size());
  std::vector<float> firstImage;
  for (int repetition = 0; repetition < settings.repetitions; ++repetition) {
    for (std::size_t k = 0; k < example.rows.size(); ++k) {
      const std::size_t i = (k + std::size_t(repetition)) % example.rows.size();
      const render::RenderResult result = render::render(description, *scenes[i], render);
      seconds[i].push_back(result.seconds);
      if (repetition > 0) continue;
      PaperTableRow& row = example.rows[i];
      row.cameraRays = result.rays.camera, row.bounceRays = result.rays.bounce, row.shadowRays = result.rays.shadow;
      if (i == 0) firstImage = result.image.pixels;
      row.sameImage = i == 0 || result.image.pixels == firstImage;
    }
  }
  for (std::size_t i = 0; i < example.rows.size(); ++i) {
    PaperTableRow& row = example.rows[i];
    row.renderSeconds = median(seconds[i]);
    row.renderLow = *std::min_element(seconds[i].begin(), seconds[i].end());
    row.renderHigh = *std::max_element(seconds[i].begin(), seconds[i].end());
    // The counters cost time, so they come from a render of their own.
    const scene::EmbreeScene counted(description, scene::BuildSettings{.options = row.options, .countStats = true});
    render::render(description, counted, render);
    row.counters = counted.stats();
    row.treeNodes = counted.treeNodeCount();
  }
}

// The paper's "percent of nodes traversed", read as nodes visited over what visiting every node of
// every object's tree for every ray would cost.
double nodesPercent(const PaperTableRow& row) {
  const double all = double(row.rays()) * double(row.treeNodes);
  return all > 0 ? 100.0 * double(row.counters.nodesVisited) / all : 0.0;
}

double improvedPercent(const PaperTableRow& row, const PaperTableRow& kajiya) {
  return 100.0 * (kajiya.totalSeconds() / row.totalSeconds() - 1.0);
}

const PaperRow* paperRowFor(const PaperExample& example, const PaperTableRow& row) {
  if (row.label == "wide") return nullptr;
  for (const PaperRow& paper : example.paper.rows) {
    if (row.label == "KJ" && std::string(paper.shell) == "KJ") return &paper;
    if (row.label != "KJ" && row.options.monotoneSplit && row.label == paper.shell &&
        row.options.rangeSearch == paper.rangeSearch) {
      return &paper;
    }
  }
  return nullptr;
}

std::string optionalText(const std::optional<double>& value, const char* format) {
  if (!value) return "-";
  char text[32];
  std::snprintf(text, sizeof text, format, *value);
  return text;
}

}  // namespace

std::vector<PaperExample> runPaperTable(const PaperTableSettings& settings) {
  const io::SceneDescription description = io::readScene(settings.scene);
  // The first Embree device and TBB pool of a process pay a start-up cost that belongs to no row.
  { const scene::EmbreeScene warmUp(description, scene::BuildSettings{}); }
  std::vector<PaperExample> examples = {{"Example 1", 1, false, paperTable2(), {}},
                                        {"Example 2", 4, true, paperTable4(), {}}};
  for (PaperExample& example : examples) runExample(description, settings, example);
  return examples;
}

void printPaperTable(std::FILE* out, const PaperTableSettings& settings, const std::vector<PaperExample>& examples) {
  for (const PaperExample& example : examples) {
    std::fprintf(out, "\n== %s: %s, %d x %d, 1 sample a pixel, whitted depth %d, %s; %d thread%s, median of %d\n",
                 example.name.c_str(), settings.scene.c_str(), settings.size, settings.size, example.depth,
                 example.shadows ? "shadows" : "no shadows", settings.threads, settings.threads == 1 ? "" : "s",
                 settings.repetitions);
    std::fprintf(out, "%-16s %-82s | Baciu, Jia & Lam 2001, Table %d (Pentium III 450 MHz)\n", "",
                 "revolve, this machine", example.paper.number);
    std::fprintf(out, "%-5s %-3s %-3s %9s %9s %9s %9s %9s %9s %9s | %8s %9s %7s %8s %8s\n", "row", "MI", "RS", "time s",
                 "improved", "nodes", "shells M", "quads M", "render s", "Mrays/s", "time s", "improved", "nodes",
                 "shells M", "quads M");
    const PaperTableRow& kajiya = example.rows.front();
    for (const PaperTableRow& row : example.rows) {
      const bool kj = row.label == "KJ";
      const char* mi = kj ? "-" : row.options.monotoneSplit ? "yes" : "no";
      const char* rs = kj ? "-" : row.options.rangeSearch ? "yes" : "no";
      char improved[16] = "--";
      if (!kj) std::snprintf(improved, sizeof improved, "%.1f%%", improvedPercent(row, kajiya));
      std::fprintf(out, "%-5s %-3s %-3s %9.4f %9s %8.4f%% %9.4f %9.4f %9.4f %9.2f |", row.label.c_str(), mi, rs,
                   row.totalSeconds(), improved, nodesPercent(row), 1e-6 * double(row.counters.shellTests),
                   1e-6 * double(row.counters.quadratics), row.renderSeconds,
                   1e-6 * double(row.rays()) / row.renderSeconds);
      if (const PaperRow* paper = paperRowFor(example, row)) {
        std::fprintf(
            out, " %7.2f%s %9s %7s %8s %8s", paper->seconds, paper->derived ? "*" : " ",
            optionalText(paper->improvedPercent, "%.2f%%").c_str(), optionalText(paper->nodesPercent, "%.2f%%").c_str(),
            optionalText(paper->shellMillions, "%.2f").c_str(), optionalText(paper->quadraticMillions, "%.2f").c_str());
      }
      std::fprintf(out, "%s\n", row.sameImage ? "" : "  (image differs from KJ's)");
    }
    for (const PaperRow& paper : example.paper.rows) {
      if (std::string(paper.shell) != "?") continue;
      std::fprintf(
          out,
          "  Table %d also has a row with range search, its shell illegible in our copy: %.2f s, %s improved, %s "
          "nodes, %s M shells, %s M quadratics\n",
          example.paper.number, paper.seconds, optionalText(paper.improvedPercent, "%.2f%%").c_str(),
          optionalText(paper.nodesPercent, "%.2f%%").c_str(), optionalText(paper.shellMillions, "%.2f").c_str(),
          optionalText(paper.quadraticMillions, "%.2f").c_str());
    }
    for (const PaperRow& paper : example.paper.rows) {
      if (paper.derived)
        std::fprintf(out, "  * Table %d's KJ time follows from its rows' times and percentages\n",
                     example.paper.number);
    }
  }
  std::fprintf(
      out,
      "\ntime = build + render; improved = KJ's time / the row's - 1; nodes = nodes visited / (rays x tree nodes "
      "of all objects); shells = bounding-shell (KJ: strip) tests; quads = ray/cone quadratics; rays = camera "
      "+ reflected/refracted + shadow\n");
}

nlohmann::ordered_json paperTableJson(const PaperTableSettings& settings, const std::vector<PaperExample>& examples) {
  nlohmann::ordered_json json;
  json["settings"] = {{"scene", settings.scene},
                      {"width", settings.size},
                      {"height", settings.size},
                      {"spp", 1},
                      {"integrator", "whitted"},
                      {"threads", settings.threads},
                      {"repetitions", settings.repetitions}};
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const PaperExample& example : examples) {
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    const PaperTableRow& kajiya = example.rows.front();
    for (const PaperTableRow& row : example.rows) {
      nlohmann::ordered_json entry;
      entry["row"] = row.label;
      entry["method"] = methodName(row.options.method);
      entry["monotone_split"] = row.options.method == Method::mibit && row.options.monotoneSplit;
      entry["range_search"] = row.options.method == Method::mibit && row.options.rangeSearch;
      entry["wide_tree"] = row.label == "wide";
      entry["total_seconds"] = row.totalSeconds();
      entry["build_seconds"] = row.buildSeconds;
      entry["render_seconds"] = {{"median", row.renderSeconds}, {"low", row.renderLow}, {"high", row.renderHigh}};
      entry["improved_percent"] = row.label == "KJ" ? 0.0 : improvedPercent(row, kajiya);
      entry["speedup_over_kj"] = kajiya.totalSeconds() / row.totalSeconds();
      entry["nodes_traversed_percent"] = nodesPercent(row);
      entry["shell_tests_millions"] = 1e-6 * double(row.counters.shellTests);
      entry["quadratics_millions"] = 1e-6 * double(row.counters.quadratics);
      entry["mrays_per_second"] = 1e-6 * double(row.rays()) / row.renderSeconds;
      entry["rays"] = {
          {"camera", row.cameraRays}, {"bounce", row.bounceRays}, {"shadow", row.shadowRays}, {"total", row.rays()}};
      entry["counters"] = {{"queries", row.counters.rays},
                           {"nodes_visited", row.counters.nodesVisited},
                           {"shell_tests", row.counters.shellTests},
                           {"quadratics", row.counters.quadratics},
                           {"tree_nodes", row.treeNodes}};
      entry["same_image_as_kj"] = row.sameImage;
      rows.push_back(entry);
    }
    nlohmann::ordered_json paper = nlohmann::ordered_json::array();
    for (const PaperRow& row : example.paper.rows) {
      const auto optional = [](const std::optional<double>& v) {
        return v ? nlohmann::ordered_json(*v) : nlohmann::ordered_json();
      };
      paper.push_back({{"shell", row.shell},
                       {"range_search", row.rangeSearch},
                       {"seconds", row.seconds},
                       {"improved_percent", optional(row.improvedPercent)},
                       {"nodes_percent", optional(row.nodesPercent)},
                       {"shell_millions", optional(row.shellMillions)},
                       {"quadratic_millions", optional(row.quadraticMillions)},
                       {"derived", row.derived}});
    }
    list.push_back(
        {{"example", example.name},
         {"depth", example.depth},
         {"shadows", example.shadows},
         {"rows", rows},
         {"paper", {{"table", example.paper.number}, {"machine", "Pentium III 450 MHz, 256 MB"}, {"rows", paper}}}});
  }
  json["examples"] = list;
  return json;
}

}  // namespace revolve::bench
