#include "bench/surface/surface_bench.h"

#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>

#include "bench/registry.h"
#include "bench/simulated_scan.h"
#include "bench/surface/scan_surface_case.h"
#include "bench/surface/surface_case.h"
#include "bench/surface/surface_targets.h"

namespace avc::bench {
namespace {

void PrintTable(const std::vector<SurfaceCaseResult>& cases, const SurfaceCaseOptions& options) {
  std::cout << fmt::format(
      "\nSurface reconstruction on {} points sampled on each plant's leaves ({:.1f} mm noise),\n"
      "against the leaves' one-sided ground truth; RMSE and mean of mesh area samples to it.\n"
      "Baselines ignore the clusters. Time: median of {}, meshing only (+ clustering for\n"
      "Algorithm 2 in the last column).\n",
      options.points, 1e3 * options.noise, options.repeats);
  std::cout << fmt::format("{:<10} {:<20} {:>6} {:>8} {:>8} {:>9} {:>6} {:>6} {:>7} {:>8} {:>9}\n",
                           "plant", "method", "area", "RMSE mm", "mean mm", "leaves 1c", "strict",
                           "height", "faces", "mesh s", "cluster s");
  for (const SurfaceCaseResult& c : cases) {
    for (const SurfaceMethodResult& m : c.methods) {
      const std::string lead = fmt::format("{:<10} {:<20}", c.preset, m.method);
      if (!m.ok) {
        std::cout << lead << " FAILED: " << m.error << "\n";
        continue;
      }
      std::cout << fmt::format(
          "{} {:>6.3f} {:>8.3f} {:>8.3f} {:>3}/{:<3} {:>3.0f}% {:>6} {:>6.3f} {:>7} {:>8.3f} "
          "{:>9}\n",
          lead, m.area_ratio, 1e3 * m.rmse, 1e3 * m.mean, m.connected_leaves, m.leaves,
          100 * m.connected_fraction, m.connected_leaves_strict, m.height_ratio, m.faces, m.seconds,
          m.cluster_seconds > 0 ? fmt::format("{:.3f}", m.cluster_seconds) : std::string("-"));
    }
    std::cout << fmt::format("{:<10} spacing {:.2f} mm, truth area {:.1f} cm^2\n", "",
                             1e3 * c.spacing, 1e4 * c.truth_area);
  }
}

nlohmann::json ToJson(const std::vector<SurfaceCaseResult>& cases,
                      const std::vector<TargetCheck>& checks, const SurfaceCaseOptions& options) {
  nlohmann::json rows = nlohmann::json::array();
  for (const SurfaceCaseResult& c : cases) {
    for (const SurfaceMethodResult& m : c.methods) {
      nlohmann::json row = {{"preset", c.preset},
                            {"method", m.method},
                            {"points", c.points},
                            {"spacing_m", c.spacing},
                            {"truth_area_m2", c.truth_area},
                            {"ok", m.ok}};
      if (!m.ok) {
        row["error"] = m.error;
      } else {
        row.update({{"area_ratio", m.area_ratio},
                    {"rmse_m", m.rmse},
                    {"mean_m", m.mean},
                    {"leaves", m.leaves},
                    {"connected_leaves", m.connected_leaves},
                    {"connected_leaves_strict", m.connected_leaves_strict},
                    {"connected_fraction", m.connected_fraction},
                    {"height_ratio", m.height_ratio},
                    {"faces", m.faces},
                    {"seconds", m.seconds},
                    {"cluster_seconds", m.cluster_seconds}});
      }
      rows.push_back(row);
    }
  }
  nlohmann::json targets = nlohmann::json::array();
  for (const TargetCheck& check : checks) {
    targets.push_back({{"target", check.target}, {"met", check.met}, {"detail", check.detail}});
  }
  return {{"benchmark", "surface"}, {"points", options.points},   {"noise_m", options.noise},
          {"seed", options.seed},   {"repeats", options.repeats}, {"rows", rows},
          {"targets", targets}};
}

void PrintScanTable(const std::vector<ScanSurfaceRow>& rows) {
  std::cout << "\nPhase 2 on real reconstructions: each plant's simulated 3 x 10 scan through the\n"
               "builder (automatic masks, proxy, patch MVS, merging) and Algorithm 2; the same\n"
               "clusters surfaced with the band growth (no images) and with the image-driven\n"
               "level sets; the meshes scored against the plant's leaves (as avc bench e2e).\n"
               "ground mm: where the height trait starts (the soil the builder found, or the\n"
               "proxy's base) minus the true soil's height. leaves 1c: leaves whose faces are\n"
               "one piece (faces given to the nearest organ, ambiguous ones settled); 95%: leaves\n"
               "whose largest piece holds at least 95 % of their faces' area.\n";
  std::cout << fmt::format(
      "{:<10} {:<24} {:>6} {:>7} {:>10} {:>7} {:>7} {:>8} {:>10} {:>7} {:>11} {:>9} {:>6} {:>7} "
      "{:>8}\n",
      "plant", "Phase 2", "images", "merged", "leaf area", "P@2mm", "R@2mm", "acc mm", "area trait",
      "height", "ground mm", "leaves 1c", "95%", "faces", "surf s");
  for (const ScanSurfaceRow& row : rows) {
    const std::string lead = fmt::format("{:<10} {:<24}", row.preset, row.method);
    if (!row.ok) {
      std::cout << lead << " FAILED: " << row.error << "\n";
      continue;
    }
    std::cout << fmt::format(
        "{} {:>6} {:>7} {:>10.3f} {:>6.1f}% {:>6.1f}% {:>8.3f} {:>10.3f} {:>7.3f} {:>+6.2f} {:<4} "
        "{:>9} {:>6} {:>7} {:>8.2f}\n",
        lead, row.images, row.merged_points, row.leaf_area_ratio, 100 * row.precision_2mm,
        100 * row.recall_2mm, 1e3 * row.accuracy_mean, row.total_area_ratio, row.height_ratio,
        1e3 * row.ground_error, row.soil_found ? "soil" : "base",
        fmt::format("{}/{}", row.connected_leaves, row.leaves),
        fmt::format("{}/{}", row.mostly_one_leaves, row.leaves), row.faces, row.seconds);
  }
}

int RunScanRows(const std::vector<std::string>& presets, const std::string& work_dir,
                const surface::ImageGrowthOptions& growth) {
  const std::filesystem::path work =
      work_dir.empty()
          ? std::filesystem::temp_directory_path() / fmt::format("avc-bench-surface-{}", getpid())
          : std::filesystem::path(work_dir);
  std::vector<ScanSurfaceRow> rows;
  bool failed = false;
  for (const std::string& preset : presets) {
    const std::optional<std::filesystem::path> scan = EnsureSimulatedScan(work, preset);
    if (!scan) {
      failed = true;
      continue;
    }
    std::cerr << fmt::format("  {}: builder, Algorithm 2, surfacer twice\n", preset);
    for (ScanSurfaceRow& row : RunScanSurfaceCase(preset, *scan, growth)) {
      failed = failed || !row.ok;
      rows.push_back(std::move(row));
    }
  }
  PrintScanTable(rows);
  if (work_dir.empty()) std::filesystem::remove_all(work);
  return failed ? 1 : 0;
}

}  // namespace

int RunSurfaceBenchmark(const std::vector<std::string>& arguments) {
  std::vector<std::string> presets = {"rosette", "broadleaf", "strap", "bushy"};
  SurfaceCaseOptions options;
  bool json = false;
  CLI::App app{
      "avc bench surface: the surfacer (paper §4, Algorithm 3) against trimmed PCL Poisson, PCL\n"
      "greedy projection, CGAL advancing front and Pound-style fixed-radius planar patches, on\n"
      "points sampled uniformly on the leaves of each simulated plant, clustered one cluster\n"
      "per leaf and by the paper's Algorithm 2 (paper Table 4: area and accuracy).",
      "avc bench surface"};
  app.add_option("--presets", presets, "simulated plants")->delimiter(',')->capture_default_str();
  app.add_option("--points", options.points, "points sampled on each plant's leaves")
      ->capture_default_str()
      ->check(CLI::Range(100, 1000000));
  app.add_option("--seed", options.seed, "plant and sampling seed")->capture_default_str();
  app.add_option("--repeats", options.repeats, "timed runs per method (median reported)")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  app.add_flag("--json", json, "print the results as one JSON line at the end");
  bool scans = false;
  std::string work_dir;
  app.add_flag("--scans", scans,
               "instead: Phase 2 with and without images on each plant's simulated scan, "
               "through the builder and Algorithm 2 (renders the scans first: minutes)");
  app.add_option("--work-dir", work_dir,
                 "with --scans: keep the rendered scans here and reuse them (default: a "
                 "temporary folder, removed at the end)");
  surface::ImageGrowthOptions growth;
  app.add_option("--max-growth-factor", growth.max_growth_factor,
                 "with --scans: how far the image level sets may grow a cell, in spacings")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  if (const auto exit_code = ParseBenchmarkArguments(app, arguments)) return *exit_code;
  if (scans) return RunScanRows(presets, work_dir, growth);

  std::vector<SurfaceCaseResult> cases;
  for (const std::string& name : presets) {
    sim::PlantPreset preset;
    try {
      preset = sim::ParsePreset(name);
    } catch (const std::invalid_argument& error) {
      std::cerr << "avc bench surface: " << error.what() << "\n";
      return 2;
    }
    std::cerr << fmt::format("  {}: {} points, {} repeats\n", name, options.points,
                             options.repeats);
    cases.push_back(RunSurfaceCase(preset, options));
  }
  PrintTable(cases, options);
  const std::vector<TargetCheck> checks = CheckSurfaceTargets(cases);
  std::cout << "\nTargets (ours, both clusterings, every preset):\n";
  for (const TargetCheck& check : checks) {
    std::cout << fmt::format("  {:<34} {}{}\n", check.target, check.met ? "met" : "NOT met",
                             check.detail.empty() ? "" : " (" + check.detail + ")");
  }
  if (json) std::cout << ToJson(cases, checks, options).dump() << "\n";
  bool failed = false;
  for (const SurfaceCaseResult& c : cases) {
    for (const SurfaceMethodResult& m : c.methods) failed = failed || !m.ok;
  }
  return failed ? 1 : 0;
}

}  // namespace avc::bench
