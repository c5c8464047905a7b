// avc bench chaos: scans in the simulated cell survive crashes. An undisturbed reference scan
// first; then seeded trials, each SIGKILLing one process (the simulator, a driver, the recorder or
// `avc scan` itself) at a random moment, the process restarted or the scan resumed; then several
// cells with different ids scanning at once on the same multicast groups. Every scan must end
// with each image exactly once, the reference's kept images and its mesh byte for byte.

#include "bench/chaos/chaos_bench.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "bench/chaos/chaos_plan.h"
#include "bench/chaos/chaos_report.h"
#include "bench/devices/scan_process.h"
#include "bench/registry.h"

namespace avc::bench {
namespace {
namespace fs = std::filesystem;

struct ChaosBenchArgs {
  int trials = 20;
  uint64_t seed = 1;
  int cells = 3;
  std::vector<std::string> victims = ChaosVictims();
  std::string plant = "strap";
  int triangles = 8000;
  int width = 1280, height = 960;
  int max_views = 14;
  double time_scale = 20;
  int port = 7790;  // control multicast port; bulk is port + 1
  std::string work_dir = "/tmp/avc-bench-chaos";
  bool json = false;
};

class ChaosBench {
 public:
  explicit ChaosBench(const ChaosBenchArgs& args) : args_(args), work_(args.work_dir) {
    fs::create_directories(work_);
    calibration_ = work_ / "calibration.yaml";
    WriteNominalCalibration(calibration_, args.width, args.height);
  }

  int Run() {
    std::cerr << fmt::format("reference scan ({} plant, {} triangles, {}x{}, {}x clock)\n",
                             args_.plant, args_.triangles, args_.width, args_.height,
                             args_.time_scale);
    reference_ = {"reference", RunChaosScan(Options("reference", "cell-a", std::nullopt)), {}};
    reference_.comparison = CompareWithReference(reference_.result, reference_.result);
    if (!reference_.comparison.ok()) {
      PrintChaosTable(std::cout, "Reference scan", {reference_});
      std::cout << reference_.result.error << "\n";
      return 1;
    }
    ChaosPlanOptions plan;
    plan.trials = args_.trials;
    plan.seed = args_.seed;
    plan.victims = args_.victims;
    plan.scan_wall_s = reference_.result.wall_s;
    const std::vector<ChaosFault> faults =
        args_.trials > 0 ? PlanChaosFaults(plan) : std::vector<ChaosFault>{};
    for (size_t i = 0; i < faults.size(); ++i) {
      const std::string name = fmt::format("trial-{:02d}", i + 1);
      std::cerr << fmt::format("{} of {}: SIGKILL {} at {:.1f} s\n", name, faults.size(),
                               faults[i].victim, faults[i].at_s);
      trials_.push_back(Trial(name, faults[i]));
    }
    if (args_.cells > 0) RunCells();
    return Report();
  }

 private:
  ChaosScanOptions Options(const std::string& name, const std::string& cell,
                           const std::optional<ChaosFault>& fault) const {
    const fs::path dir = work_ / name;
    fs::remove_all(dir);  // a scan directory from an earlier run would be refused
    ChaosScanOptions options;
    options.label = name;
    options.cell = LocalCellOptions(args_.port, cell, args_.time_scale, dir / "cell");
    options.cell.plant = args_.plant;
    options.cell.triangles = args_.triangles;
    options.cell.width = args_.width;
    options.cell.height = args_.height;
    options.cell.png = true;  // lossless, so equal views give equal bytes
    options.cell.extra_sim_args = {"--nominal-cell"};
    options.scan_dir = dir / "plant";
    options.calibration = calibration_;
    options.planner_args = {"--max-views", std::to_string(args_.max_views), "--views-per-height",
                            "6"};
    options.fault = fault;
    return options;
  }

  // A scan that ran faster than the reference may end before its moment: it runs again, killed
  // at the same fraction of its own wall time.
  ChaosRow Trial(const std::string& name, const ChaosFault& fault) const {
    ChaosScanResult result = RunChaosScan(Options(name, "cell-a", fault));
    if (result.error.empty() && !result.fault_injected) {
      ChaosFault again = fault;
      again.at_s = std::max(2.0, fault.at_s * result.wall_s / reference_.result.wall_s);
      std::cerr << fmt::format(
          "{}: done in {:.1f} s, before the kill; again with the kill at {:.1f} s\n", name,
          result.wall_s, again.at_s);
      result = RunChaosScan(Options(name, "cell-a", again));
    }
    return Compared(name, std::move(result));
  }

  ChaosRow Compared(const std::string& name, ChaosScanResult result) const {
    ChaosRow row{name, std::move(result), {}};
    row.comparison = CompareWithReference(reference_.result, row.result);
    if (!row.result.error.empty()) std::cerr << row.result.error << "\n";
    return row;
  }

  // Every cell on the same multicast groups, told apart only by its id.
  void RunCells() {
    std::vector<ChaosScanOptions> scans;
    for (int i = 0; i < args_.cells; ++i) {
      const std::string cell = fmt::format("cell-{}", static_cast<char>('a' + i));
      scans.push_back(Options("cells-" + cell, cell, std::nullopt));
    }
    std::cerr << fmt::format("{} cells scanning at once on ports {} and {}\n", args_.cells,
                             args_.port, args_.port + 1);
    const auto start = std::chrono::steady_clock::now();
    std::vector<ChaosScanResult> results = RunConcurrentChaosScans(scans);
    cells_wall_s_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (ChaosScanResult& result : results) {
      const std::string name = result.label;
      cells_.push_back(Compared(name, std::move(result)));
    }
  }

  int Report() const {
    PrintChaosTable(std::cout, "Reference scan (undisturbed)", {reference_});
    if (!trials_.empty()) {
      PrintChaosTable(std::cout,
                      fmt::format("Chaos trials (seed {}): one SIGKILL each, then restart or "
                                  "resume; compared with the reference",
                                  args_.seed),
                      trials_);
    }
    if (!cells_.empty()) {
      PrintChaosTable(std::cout,
                      fmt::format("{} cells at once on one network (ports {}/{}), compared with "
                                  "the reference",
                                  cells_.size(), args_.port, args_.port + 1),
                      cells_);
    }
    const bool passed = PrintChaosSummary(std::cout, reference_, trials_, cells_, cells_wall_s_);
    for (const std::vector<ChaosRow>* group : {&trials_, &cells_}) {
      for (const ChaosRow& row : *group) {
        for (const std::string& problem : row.comparison.problems) {
          std::cout << fmt::format("  {}: {}\n", row.name, problem);
        }
      }
    }
    if (args_.json) std::cout << Json(passed).dump() << "\n";
    return passed ? 0 : 1;
  }

  nlohmann::json Json(bool passed) const {
    nlohmann::json json = {{"benchmark", "chaos"},
                           {"seed", args_.seed},
                           {"plant", args_.plant},
                           {"triangles", args_.triangles},
                           {"width", args_.width},
                           {"height", args_.height},
                           {"time_scale", args_.time_scale},
                           {"passed", passed},
                           {"reference", ChaosRowJson(reference_)},
                           {"trials", nlohmann::json::array()},
                           {"cells", nlohmann::json::array()},
                           {"cells_wall_s", cells_wall_s_}};
    for (const ChaosRow& row : trials_) json["trials"].push_back(ChaosRowJson(row));
    for (const ChaosRow& row : cells_) json["cells"].push_back(ChaosRowJson(row));
    return json;
  }

  const ChaosBenchArgs& args_;
  fs::path work_, calibration_;
  ChaosRow reference_;
  std::vector<ChaosRow> trials_, cells_;
  double cells_wall_s_ = 0;
};

}  // namespace

int RunChaosBenchmark(const std::vector<std::string>& arguments) {
  ChaosBenchArgs args;
  CLI::App app{
      "avc bench chaos: scans in the simulated cell that survive crashes. A reference scan, then\n"
      "--trials scans that each SIGKILL one process at a random moment (5-90 % of the reference's\n"
      "wall time, victims in a seeded balanced shuffle: avc-sim, avc-robot, avc-turntable,\n"
      "avc-camera, avc-record, the services avc-planner, avc-builder, avc-clusterer and\n"
      "avc-surfacer, avc-scan); a killed cell process or service is restarted, a killed or\n"
      "faulted scan resumed with `avc scan --resume`; a scan that ends before its moment runs\n"
      "again, killed at the same fraction of its own time. Then --cells cells (cell-a, cell-b,\n"
      "...) scan at once on the same multicast groups. Each scan must hold every image exactly\n"
      "once, the reference's kept images and a byte-identical mesh.ply. Exit 1 if any check\n"
      "fails.",
      "avc bench chaos"};
  app.add_option("--trials", args.trials, "scans with one kill each")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000));
  app.add_option("--seed", args.seed, "seeds the victims and the moments")->capture_default_str();
  app.add_option("--cells", args.cells, "cells scanning at once at the end (0: none)")
      ->capture_default_str()
      ->check(CLI::Range(0, 26));
  app.add_option("--victims", args.victims, "processes the trials may kill")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::IsMember(ChaosVictims()));
  app.add_option("--plant", args.plant, "plant preset: rosette, broadleaf, strap, bushy")
      ->capture_default_str();
  app.add_option("--triangles", args.triangles, "plant triangles")->capture_default_str();
  app.add_option("--width", args.width, "image width")->capture_default_str();
  app.add_option("--height", args.height, "image height")->capture_default_str();
  app.add_option("--max-views", args.max_views, "most images a scan captures")
      ->capture_default_str()
      ->check(CLI::Range(4, 200));
  app.add_option("--time-scale", args.time_scale, "simulated seconds per real second")
      ->capture_default_str()
      ->check(CLI::Range(0.01, 1000.0));
  app.add_option("--port", args.port, "multicast port of the control bus (bulk: +1)")
      ->capture_default_str();
  app.add_option("--work-dir", args.work_dir, "scans and logs, one folder per scan (replaced)")
      ->capture_default_str();
  app.add_flag("--json", args.json, "print the results as one JSON line at the end");
  if (const auto exit_code = ParseBenchmarkArguments(app, arguments)) return *exit_code;
  return ChaosBench(args).Run();
}

}  // namespace avc::bench
