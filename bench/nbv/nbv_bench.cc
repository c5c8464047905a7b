#include "bench/nbv/nbv_bench.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <iostream>

#include "bench/mvs/isolated_run.h"
#include "bench/nbv/nbv_case.h"
#include "bench/registry.h"

namespace avc::bench {
namespace {

std::string Percent(const nlohmann::json& method, const char* key) {
  return method.contains(key) ? fmt::format("{:.1f}%", 100 * method[key].get<double>()) : "-";
}

void PrintPlant(const NbvCase& nbv_case, const IsolatedResult& run) {
  std::cout << fmt::format("\n{}", nbv_case.plant);
  if (!run.ok) {
    std::cout << ": FAILED: " << run.error << "\n";
    return;
  }
  const nlohmann::json& r = run.result;
  std::cout << fmt::format(" ({} ground-truth samples, {} renders, peak {:.0f} MB)\n",
                           r["samples"].get<size_t>(), r["renders"].get<int>(), run.peak_memory_mb);
  std::cout << fmt::format("{:<38} {:>7} {:>9} {:>9} {:>9} {:>9} {:>8} {:>8} {:>8} {:>8}\n",
                           "method", "images", "coverage", "after 10", "after 20", "after 30",
                           "to 90%", "points", "pts/img", "mean mm");
  for (const nlohmann::json& m : r["methods"]) {
    std::cout << fmt::format(
        "{:<38} {:>7} {:>9} {:>9} {:>9} {:>9} {:>8} {:>8} {:>8} {:>8}\n",
        m["method"].get<std::string>(), m["images"].get<size_t>(), Percent(m, "coverage"),
        Percent(m, "after_10"), Percent(m, "after_20"), Percent(m, "after_30"),
        m.contains("images_to_90") ? std::to_string(m["images_to_90"].get<int>()) : "-",
        m.contains("points") ? std::to_string(m["points"].get<size_t>()) : "-",
        m.contains("points_per_image") ? fmt::format("{:.0f}", m["points_per_image"].get<double>())
                                       : "-",
        m.contains("mean_distance_mm") ? fmt::format("{:.3f}", m["mean_distance_mm"].get<double>())
                                       : "-");
    if (m.contains("build_error")) {
      std::cout << "  build failed: " << m["build_error"].get<std::string>() << "\n";
    }
  }
  const nlohmann::json& ours = r["methods"][0];
  std::cout << fmt::format("ours: {} captured, {} kept; {} patches, {} below the target",
                           ours["captured"].get<size_t>(), ours["images"].get<size_t>(),
                           ours["patches"].get<int>(), ours["failing_patches"].get<int>());
  if (ours.contains("planning_s_median")) {
    std::cout << fmt::format(
        "; planning {:.2f} s per chosen view (search {:.2f} s median, {:.2f} s max of {})",
        ours["planning_s_per_view"].get<double>(), ours["planning_s_median"].get<double>(),
        ours["planning_s_max"].get<double>(), ours["iterations"].get<int>());
  }
  std::cout << "\n";
  for (const auto& note : ours["notes"]) std::cout << "  note: " << note.get<std::string>() << "\n";
}

}  // namespace

int RunNbvBenchmark(const std::vector<std::string>& arguments) {
  std::vector<std::string> presets = {"rosette", "broadleaf", "strap", "bushy"};
  std::vector<std::string> meshes;
  bool json = false;
  // Every plant's case is a copy of this one, with the options bound to it directly.
  NbvCase settings;
  CLI::App app{
      "avc bench nbv: the planner's active vision (Algorithm 1: framing, the 3x10 orbit,\n"
      "view-sphere search for badly seen proxy patches, redundant-view removal) in the\n"
      "simulated cell, against one and two static cameras with the turntable, random reachable\n"
      "views and the 3x10 orbit alone, scored by ground-truth coverage (seen by >= 3 views at\n"
      "a grazing angle under 75 degrees). Each plant runs in its own process.",
      "avc bench nbv"};
  app.add_option("--presets", presets, "simulated plants")->delimiter(',')->capture_default_str();
  app.add_option("--mesh", meshes, "also a plant mesh file (PLY/OBJ/OFF, metres)")
      ->check(CLI::ExistingFile);
  app.add_option("--render-scale", settings.render_scale, "capture resolution over the camera's")
      ->capture_default_str()
      ->check(CLI::Range(0.1, 1.0));
  app.add_option("--views", settings.baseline_views, "images of each baseline")
      ->capture_default_str()
      ->check(CLI::Range(3, 200));
  app.add_option("--capture-budget", settings.capture_budget,
                 "captures the planner may take before removing redundant ones")
      ->capture_default_str()
      ->check(CLI::Range(30, 200));
  app.add_option("--prune-face-loss", settings.prune_face_loss,
                 "fraction of the proxy faces covered by all captures that Phase 3 may leave "
                 "under 3 views (1: the paper's rule alone)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--elevations", settings.elevations_deg, "Phase 1's three heights, degrees")
      ->delimiter(',')
      ->expected(3)
      ->check(CLI::Range(0.0, 89.0));
  app.add_option("--seed", settings.seed, "coverage sampling and random-view seed")
      ->capture_default_str();
  app.add_flag("--build", settings.build,
               "also run the builder (patch MVS) on every view set but the ceiling and score its "
               "points against the plant: the paper's Table 1 (minutes per plant)");
  app.add_flag("--json", json, "print the results as one JSON line at the end");
  if (const auto exit_code = ParseBenchmarkArguments(app, arguments)) return *exit_code;

  std::vector<NbvCase> cases;
  for (const std::string& preset : presets) {
    if (preset.empty()) continue;
    cases.push_back(settings);
    cases.back().plant = preset;
  }
  for (const std::string& mesh : meshes) {
    cases.push_back(settings);
    cases.back().plant = std::filesystem::path(mesh).stem().string();
    cases.back().mesh_file = mesh;
  }
  nlohmann::json report = {{"benchmark", "nbv"}, {"plants", nlohmann::json::array()}};
  bool failed = false;
  for (const NbvCase& nbv_case : cases) {
    std::cerr << "planning " << nbv_case.plant << "\n";
    const IsolatedResult run = RunIsolated([&] { return RunNbvCase(nbv_case); });
    PrintPlant(nbv_case, run);
    failed = failed || !run.ok;
    nlohmann::json entry = run.ok ? run.result : nlohmann::json{{"plant", nbv_case.plant}};
    entry["peak_memory_mb"] = run.peak_memory_mb;
    if (!run.ok) entry["error"] = run.error;
    report["plants"].push_back(entry);
  }
  if (json) std::cout << report.dump() << "\n";
  return failed ? 1 : 0;
}

}  // namespace avc::bench
