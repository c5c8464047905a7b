#include "bench/mvs/mvs_bench.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "bench/mvs/isolated_run.h"
#include "bench/mvs/mvs_bench_case.h"
#include "bench/mvs/ppr_bench_case.h"
#include "bench/registry.h"
#include "bench/simulated_scan.h"
#include "bench/summary.h"

namespace avc::bench {
namespace {

namespace fs = std::filesystem;

// PMVS2 on the same 16 images on a 2-core machine (the reference run).
struct PmvsReference {
  int level;
  double points, seconds, inside;
};
constexpr PmvsReference kPmvs[] = {{0, 69737, 24.0, 0.904}, {1, 20909, 5.6, 0.854}};

struct MvsRow {
  MvsCase mvs_case;
  std::vector<IsolatedResult> runs;
};

// Median over the successful runs of one figure; NaN when none has it.
double MedianOf(const MvsRow& row, const char* key) {
  std::vector<double> values;
  for (const IsolatedResult& run : row.runs) {
    if (run.ok && run.result.contains(key)) {
      values.push_back(std::string(key) == "peak_memory_mb" ? run.peak_memory_mb
                                                            : run.result[key].get<double>());
    }
  }
  return values.empty() ? std::nan("") : Summarize(values).median;
}

double PeakMemory(const MvsRow& row) {
  std::vector<double> values;
  for (const IsolatedResult& run : row.runs) {
    if (run.ok) values.push_back(run.peak_memory_mb);
  }
  return values.empty() ? std::nan("") : Summarize(values).median;
}

MvsRow RunRow(const MvsCase& mvs_case, int repeats) {
  MvsRow row{mvs_case, {}};
  for (int r = 0; r < repeats; ++r) {
    std::cerr << fmt::format("  {} {} level {} run {}/{}\n", mvs_case.dataset_name,
                             builder::MvsMethodName(mvs_case.method), mvs_case.level, r + 1,
                             repeats);
    row.runs.push_back(RunIsolated([&] { return RunMvsCase(mvs_case); }));
    if (!row.runs.back().ok) {
      std::cerr << "    failed: " << row.runs.back().error << "\n";
      break;
    }
  }
  return row;
}

nlohmann::json RowJson(const MvsRow& row) {
  nlohmann::json json = {{"dataset", row.mvs_case.dataset_name},
                         {"method", builder::MvsMethodName(row.mvs_case.method)},
                         {"requested_level", row.mvs_case.level},
                         {"runs", row.runs.size()},
                         {"peak_memory_mb", PeakMemory(row)}};
  for (const char* key : {"points", "points_per_image", "seconds", "mvs_seconds", "inside_fraction",
                          "precision_1mm", "recall_2mm", "mean_distance_m"}) {
    const double value = MedianOf(row, key);
    if (!std::isnan(value)) json[key] = value;
  }
  for (const IsolatedResult& run : row.runs) {
    if (!run.ok) json["error"] = run.error;
  }
  return json;
}

std::string Cell(double value, const char* format) {
  return std::isnan(value) ? "-" : fmt::format(fmt::runtime(format), value);
}

void PrintDinoTable(const std::vector<MvsRow>& rows) {
  std::cout << "\nMiddlebury dinoSparseRing, 16 images 640x480 (medians; PMVS2 = the issue's "
               "reference run)\n";
  std::cout << fmt::format("{:<14} {:>5} {:>8} {:>9} {:>8} {:>8} {:>8} {:>8}\n", "method", "level",
                           "points", "per img", "inside", "wall s", "MVS s", "peak MB");
  for (const PmvsReference& ref : kPmvs) {
    std::cout << fmt::format("{:<14} {:>5} {:>8.0f} {:>9.0f} {:>7.1f}% {:>8.1f} {:>8} {:>8}\n",
                             "PMVS2 (ref.)", ref.level, ref.points, ref.points / 16,
                             100 * ref.inside, ref.seconds, "-", "-");
  }
  for (const MvsRow& row : rows) {
    std::cout << fmt::format(
        "{:<14} {:>5} {:>8} {:>9} {:>8} {:>8} {:>8} {:>8}{}\n",
        builder::MvsMethodName(row.mvs_case.method), row.mvs_case.level,
        Cell(MedianOf(row, "points"), "{:.0f}"), Cell(MedianOf(row, "points_per_image"), "{:.0f}"),
        Cell(100 * MedianOf(row, "inside_fraction"), "{:.1f}%"),
        Cell(MedianOf(row, "seconds"), "{:.1f}"), Cell(MedianOf(row, "mvs_seconds"), "{:.1f}"),
        Cell(PeakMemory(row), "{:.0f}"), row.runs.empty() || row.runs.back().ok ? "" : "  FAILED");
  }
}

struct PprRow {
  PprCase ppr_case;
  std::vector<IsolatedResult> runs;
};

double PprMedian(const PprRow& row, const char* key) {
  std::vector<double> values;
  for (const IsolatedResult& run : row.runs) {
    if (run.ok && run.result.contains(key)) values.push_back(run.result[key].get<double>());
  }
  return values.empty() ? std::nan("") : Summarize(values).median;
}

PprRow RunPprRow(const PprCase& ppr_case, int repeats) {
  PprRow row{ppr_case, {}};
  for (int r = 0; r < repeats; ++r) {
    std::cerr << fmt::format("  {} proxy at {:.0f} mm run {}/{}\n", ppr_case.dataset_name,
                             1e3 * ppr_case.voxel_size, r + 1, repeats);
    row.runs.push_back(RunIsolated([&] { return RunPprCase(ppr_case); }));
    if (!row.runs.back().ok) {
      std::cerr << "    failed: " << row.runs.back().error << "\n";
      break;
    }
  }
  return row;
}

nlohmann::json PprRowJson(const PprRow& row) {
  nlohmann::json json = {{"dataset", row.ppr_case.dataset_name}, {"runs", row.runs.size()}};
  for (const char* key : {"views", "voxel_size_m", "occupied", "truth_voxels", "bounds_seconds",
                          "carve_seconds", "iou", "voxel_precision", "voxel_recall",
                          "ideal_occupied", "ideal_iou", "iou_with_ideal"}) {
    const double value = PprMedian(row, key);
    if (!std::isnan(value)) json[key] = value;
  }
  for (const IsolatedResult& run : row.runs) {
    if (!run.ok) json["error"] = run.error;
  }
  return json;
}

void PrintPprTable(const std::vector<PprRow>& rows) {
  std::cout << "\nPlant proxy at 2 mm from the automatic masks, against the plant's ground-truth "
               "surface voxelised on the proxy's grid (medians)\n";
  std::cout << fmt::format("{:<10} {:>6} {:>9} {:>9} {:>6} {:>9} {:>9} {:>8} {:>8} {:>9} {:>9}\n",
                           "plant", "views", "occupied", "truth", "IoU", "precision", "recall",
                           "box s", "carve s", "ideal IoU", "vs ideal");
  for (const PprRow& row : rows) {
    std::cout << fmt::format(
        "{:<10} {:>6} {:>9} {:>9} {:>6} {:>9} {:>9} {:>8} {:>8} {:>9} {:>9}{}\n",
        row.ppr_case.dataset_name, Cell(PprMedian(row, "views"), "{:.0f}"),
        Cell(PprMedian(row, "occupied"), "{:.0f}"), Cell(PprMedian(row, "truth_voxels"), "{:.0f}"),
        Cell(PprMedian(row, "iou"), "{:.3f}"), Cell(PprMedian(row, "voxel_precision"), "{:.3f}"),
        Cell(PprMedian(row, "voxel_recall"), "{:.3f}"),
        Cell(PprMedian(row, "bounds_seconds"), "{:.3f}"),
        Cell(PprMedian(row, "carve_seconds"), "{:.3f}"),
        Cell(PprMedian(row, "ideal_iou"), "{:.3f}"),
        Cell(PprMedian(row, "iou_with_ideal"), "{:.3f}"),
        row.runs.empty() || row.runs.back().ok ? "" : "  FAILED");
  }
}

void PrintSimTable(const std::vector<MvsRow>& rows) {
  std::cout << "\nSimulated plants, 30 views 1280x960, against the plant's ground truth\n";
  std::cout << fmt::format("{:<10} {:<12} {:>8} {:>8} {:>7} {:>7} {:>8} {:>7} {:>8}\n", "plant",
                           "method", "points", "per img", "P@1mm", "R@2mm", "mean mm", "wall s",
                           "peak MB");
  for (const MvsRow& row : rows) {
    std::cout << fmt::format(
        "{:<10} {:<12} {:>8} {:>8} {:>7} {:>7} {:>8} {:>7} {:>8}{}\n", row.mvs_case.dataset_name,
        builder::MvsMethodName(row.mvs_case.method), Cell(MedianOf(row, "points"), "{:.0f}"),
        Cell(MedianOf(row, "points_per_image"), "{:.0f}"),
        Cell(MedianOf(row, "precision_1mm"), "{:.3f}"), Cell(MedianOf(row, "recall_2mm"), "{:.3f}"),
        Cell(1e3 * MedianOf(row, "mean_distance_m"), "{:.3f}"),
        Cell(MedianOf(row, "seconds"), "{:.1f}"), Cell(PeakMemory(row), "{:.0f}"),
        row.runs.empty() || row.runs.back().ok ? "" : "  FAILED");
  }
}

}  // namespace

int RunMvsBenchmark(const std::vector<std::string>& arguments) {
  std::string data_dir = SharedDataDir().string();
  std::vector<std::string> presets = {"rosette", "broadleaf", "strap", "bushy"};
  int repeats = 3;
  int sim_repeats = 1;
  bool no_dino = false;
  bool scaling = true;
  bool json = false;
  bool proxy_only = false;
  std::string work_dir;
  CLI::App app{
      "avc bench mvs: the builder's patch MVS against PMVS2's published run and the\n"
      "plane-sweep comparator on the Middlebury dinoSparseRing (points, points per image,\n"
      "fraction inside every silhouette, wall time, peak memory), and on simulated plants\n"
      "(30 views at 1280x960; precision at 1 mm and recall at 2 mm against the plant's\n"
      "ground truth). Every run is a separate process, so its peak memory is its own.",
      "avc bench mvs"};
  app.add_option("--data", data_dir, "the shared data folder (AVC_SHARED_DATA)")
      ->capture_default_str();
  app.add_option("--presets", presets, "simulated plants to scan (none: --presets '')")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--repeats", repeats, "runs per dinoSparseRing case (median reported)")
      ->capture_default_str()
      ->check(CLI::Range(1, 20));
  app.add_option("--sim-repeats", sim_repeats, "runs per simulated case")
      ->capture_default_str()
      ->check(CLI::Range(1, 20));
  app.add_flag("--no-dino", no_dino, "skip the Middlebury set");
  app.add_flag("!--no-scaling", scaling,
               "skip the 1x/4x/16x pixel scaling runs (rosette at levels 2, 1, 0)");
  app.add_option("--work-dir", work_dir,
                 "where the simulated scans are rendered (default: a temporary folder, removed)");
  app.add_flag("--proxy-only", proxy_only,
               "on the simulated plants, measure the plant proxy only (no MVS)");
  app.add_flag("--json", json, "print the results as one JSON line at the end");
  if (const auto exit_code = ParseBenchmarkArguments(app, arguments)) return *exit_code;
  presets.erase(std::remove(presets.begin(), presets.end(), std::string()), presets.end());

  nlohmann::json report = {{"benchmark", "mvs"}};
  const fs::path dino = fs::path(data_dir) / "middlebury" / "dinoSparseRing";
  std::vector<MvsRow> dino_rows;
  if (!no_dino) {
    if (!fs::exists(dino)) {
      std::cerr << "dinoSparseRing not found under " << dino << " (--data); skipped\n";
    } else {
      std::cerr << "dinoSparseRing:\n";
      for (builder::MvsMethod method :
           {builder::MvsMethod::kPatch, builder::MvsMethod::kPlaneSweep}) {
        for (int level : {0, 1}) {
          dino_rows.push_back(RunRow({"dinoSparseRing", dino, method, level, true}, repeats));
        }
      }
      PrintDinoTable(dino_rows);
    }
  }

  const bool own_work_dir = work_dir.empty();
  const fs::path work = own_work_dir
                            ? fs::temp_directory_path() / fmt::format("avc-bench-mvs-{}", getpid())
                            : fs::path(work_dir);
  std::vector<MvsRow> sim_rows;
  std::vector<MvsRow> scaling_rows;
  std::vector<PprRow> ppr_rows;
  for (const std::string& preset : presets) {
    const std::optional<fs::path> rendered = EnsureSimulatedScan(work, preset);
    if (!rendered) {
      continue;
    }
    const fs::path& scan = *rendered;
    ppr_rows.push_back(RunPprRow({preset, scan, 0.002}, repeats));
    if (proxy_only) continue;
    for (builder::MvsMethod method :
         {builder::MvsMethod::kPatch, builder::MvsMethod::kPlaneSweep}) {
      sim_rows.push_back(RunRow({preset, scan, method, -1, false}, sim_repeats));
    }
    if (scaling && preset == presets.front()) {
      for (int level : {2, 1, 0}) {
        scaling_rows.push_back(
            RunRow({preset, scan, builder::MvsMethod::kPatch, level, false}, sim_repeats));
      }
    }
  }
  if (!ppr_rows.empty()) PrintPprTable(ppr_rows);
  if (!sim_rows.empty()) PrintSimTable(sim_rows);
  if (!scaling_rows.empty()) {
    std::cout << "\nScaling (patch MVS, " << presets.front()
              << "): levels 2, 1, 0 = 1x, 4x, 16x the pixels\n";
    PrintSimTable(scaling_rows);
  }
  if (own_work_dir) {
    std::error_code ignored;
    fs::remove_all(work, ignored);
  }

  for (const auto& [key, rows] :
       {std::pair{"dino", &dino_rows}, {"simulated", &sim_rows}, {"scaling", &scaling_rows}}) {
    nlohmann::json list = nlohmann::json::array();
    for (const MvsRow& row : *rows) list.push_back(RowJson(row));
    report[key] = list;
  }
  nlohmann::json ppr = nlohmann::json::array();
  for (const PprRow& row : ppr_rows) ppr.push_back(PprRowJson(row));
  report["proxy"] = ppr;
  if (json) std::cout << report.dump() << "\n";
  bool failed = false;
  for (const auto* rows : {&dino_rows, &sim_rows, &scaling_rows}) {
    for (const MvsRow& row : *rows) failed = failed || row.runs.empty() || !row.runs.back().ok;
  }
  for (const PprRow& row : ppr_rows) failed = failed || row.runs.empty() || !row.runs.back().ok;
  return failed ? 1 : 0;
}

}  // namespace avc::bench
