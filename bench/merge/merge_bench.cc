#include "bench/merge/merge_bench.h"

#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>

#include "bench/merge/merge_case.h"
#include "bench/mvs/isolated_run.h"
#include "bench/registry.h"
#include "bench/simulated_scan.h"

namespace avc::bench {
namespace {

namespace fs = std::filesystem;

struct MergeRow {
  MergeCase merge_case;
  IsolatedResult run;
};

const char* SourceName(RawSource source) {
  return source == RawSource::kPatchMvs ? "patch MVS" : "simulated";
}

void PrintMergeTable(const std::vector<MergeRow>& rows, double outlier_fraction) {
  std::cout << fmt::format(
      "\nModel merging with {:.0f} % injected outliers (distances to the plant's organs;\n"
      "removed: outside the proxy, or in occupied voxels holding fewer than 4 points)\n",
      100 * outlier_fraction);
  std::cout << fmt::format("{:<10} {:<10} {:>6} {:>8} {:>8} {:>8} {:>8} {:>9} {:>9} {:>7} {:>8}\n",
                           "plant", "raw cloud", "voxel", "raw", "merged", "outside", "sparse",
                           "raw RMSE", "mrg RMSE", "ratio", "merge s");
  for (const MergeRow& row : rows) {
    const std::string lead = fmt::format("{:<10} {:<10}", row.merge_case.dataset_name,
                                         SourceName(row.merge_case.source));
    if (!row.run.ok) {
      std::cout << lead << "  FAILED: " << row.run.error << "\n";
      continue;
    }
    const nlohmann::json& r = row.run.result;
    std::cout << fmt::format(
        "{} {:>4.1f}mm {:>8} {:>8} {:>8} {:>8} {:>7.2f}mm {:>7.2f}mm {:>6.1f}x {:>8.3f}\n", lead,
        1e3 * r["voxel_size_m"].get<double>(), r["raw_points"].get<size_t>(),
        r["merged_points"].get<size_t>(), r["outside_proxy"].get<size_t>(),
        r["in_sparse_voxels"].get<size_t>(), 1e3 * r["raw_rmse_m"].get<double>(),
        1e3 * r["merged_rmse_m"].get<double>(), r["rmse_ratio"].get<double>(),
        r["merge_seconds"].get<double>());
  }
}

}  // namespace

int RunMergeBenchmark(const std::vector<std::string>& arguments) {
  std::vector<std::string> presets = {"rosette", "broadleaf", "strap", "bushy"};
  double outlier_fraction = 0.05;
  uint64_t seed = 1;
  int repeats = 5;
  bool with_mvs = false;
  double voxel_mm = 0;
  bool json = false;
  std::string work_dir;
  CLI::App app{
      "avc bench merge: model merging (paper §3.1) on simulated scans. The builder carves the\n"
      "plant proxy from the scan's automatic masks; a raw cloud (300,000 noisy ground-truth\n"
      "samples, or with --mvs also the builder's patch MVS points) gets injected outliers and\n"
      "is merged into the proxy's voxels; both clouds are scored against the ground truth.",
      "avc bench merge"};
  app.add_option("--presets", presets, "simulated plants")->delimiter(',')->capture_default_str();
  app.add_option("--outliers", outlier_fraction, "fraction of the raw cloud that is outliers")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 0.5));
  app.add_option("--seed", seed, "sampling and outlier seed")->capture_default_str();
  app.add_option("--repeats", repeats, "timed merges per case (median reported)")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  app.add_option("--voxel-mm", voxel_mm,
                 "final proxy voxel in mm (0: the builder's automatic one, box edge / 256)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 50.0));
  app.add_flag("--mvs", with_mvs, "also merge the patch MVS points of each scan (13-50 s each)");
  app.add_option("--work-dir", work_dir,
                 "where the scans are rendered (default: a temporary folder, removed); "
                 "`avc bench mvs --work-dir` scans are reused");
  app.add_flag("--json", json, "print the results as one JSON line at the end");
  if (const auto exit_code = ParseBenchmarkArguments(app, arguments)) return *exit_code;

  const bool own_work_dir = work_dir.empty();
  const fs::path work =
      own_work_dir ? fs::temp_directory_path() / fmt::format("avc-bench-merge-{}", getpid())
                   : fs::path(work_dir);
  std::vector<MergeRow> rows;
  bool failed = false;
  for (const std::string& preset : presets) {
    const std::optional<fs::path> rendered = EnsureSimulatedScan(work, preset);
    if (!rendered) {
      failed = true;
      continue;
    }
    const fs::path& scan = *rendered;
    std::vector<RawSource> sources = {RawSource::kSimulated};
    if (with_mvs) sources.push_back(RawSource::kPatchMvs);
    for (RawSource source : sources) {
      const MergeCase merge_case{preset, scan,    source,         outlier_fraction,
                                 seed,   repeats, voxel_mm * 1e-3};
      std::cerr << fmt::format("  {}: {} cloud\n", preset, SourceName(source));
      rows.push_back({merge_case, RunIsolated([&] { return RunMergeCase(merge_case); })});
      failed = failed || !rows.back().run.ok;
    }
  }
  PrintMergeTable(rows, outlier_fraction);
  if (own_work_dir) {
    std::error_code ignored;
    fs::remove_all(work, ignored);
  }
  if (json) {
    nlohmann::json list = nlohmann::json::array();
    for (const MergeRow& row : rows) {
      nlohmann::json entry = {{"dataset", row.merge_case.dataset_name},
                              {"source", SourceName(row.merge_case.source)},
                              {"peak_memory_mb", row.run.peak_memory_mb}};
      if (row.run.ok) entry.update(row.run.result);
      if (!row.run.ok) entry["error"] = row.run.error;
      list.push_back(entry);
    }
    std::cout << nlohmann::json{{"benchmark", "merge"}, {"rows", list}}.dump() << "\n";
  }
  return failed ? 1 : 0;
}

}  // namespace avc::bench
