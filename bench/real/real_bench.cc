#include "bench/real/real_bench.h"

#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "bench/real/real_scan_figures.h"
#include "bench/real/timed_command.h"
#include "bench/registry.h"
#include "core/launch/find_program.h"

namespace avc::bench {
namespace {

namespace fs = std::filesystem;

struct RealBenchArgs {
  std::string dataset = (SharedDataDir() / "romi_arabidopsis_scan").string();
  std::string reference;  // default: <dataset>/3d/romi_mesh.ply
  std::vector<int> strides = {4, 2, 1};
  double tolerance_px = 6;
  std::vector<std::string> sets;  // passed to avc reconstruct as --set
  std::string work_dir;
  bool json = false;
};

// Slope of log(y) against log(x), least squares: the exponent of a power law y ~ x^b.
double PowerLawExponent(const std::vector<double>& x, const std::vector<double>& y) {
  double mean_x = 0, mean_y = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    mean_x += std::log(x[i]) / x.size();
    mean_y += std::log(y[i]) / y.size();
  }
  double sxy = 0, sxx = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    sxy += (std::log(x[i]) - mean_x) * (std::log(y[i]) - mean_y);
    sxx += (std::log(x[i]) - mean_x) * (std::log(x[i]) - mean_x);
  }
  return sxx > 0 ? sxy / sxx : 0.0;
}

nlohmann::json RunOne(const RealBenchArgs& args, int stride, const fs::path& output) {
  const fs::path avc = launch::SelfExecutableDir() / "avc";
  std::vector<std::string> argv = {avc.string(),  "reconstruct", "--dataset",
                                   args.dataset,  "--output",    output.string(),
                                   "--overwrite", "--stride",    std::to_string(stride)};
  for (const std::string& assignment : args.sets) {
    argv.push_back("--set");
    argv.push_back(assignment);
  }
  std::cerr << fmt::format("avc reconstruct --stride {} ...\n", stride);
  const TimedRun run = RunTimed(argv, output.string() + ".log");
  if (run.exit_code != 0) {
    throw std::runtime_error(fmt::format("avc reconstruct --stride {} {}; see {}.log", stride,
                                         run.status, output.string()));
  }
  nlohmann::json json = ReadStageTimes(output);
  json["stride"] = stride;
  json["wall_s"] = run.wall_s;
  json["peak_memory_mb"] = run.peak_memory_mb;
  return json;
}

std::string FormatRuns(const nlohmann::json& runs, double time_exponent, double proxy_exponent) {
  std::string text =
      "Cost against views (avc reconstruct as its own process, 2 cores):\n"
      "  views   wall s   peak MB   masks s   proxy s   mvs s\n";
  for (const nlohmann::json& run : runs) {
    text += fmt::format("  {:>5}  {:>7.1f}  {:>8.0f}  {:>8.2f}  {:>8.2f}  {:>6.2f}\n",
                        run["views"].get<int>(), run["wall_s"].get<double>(),
                        run["peak_memory_mb"].get<double>(), run["masks_s"].get<double>(),
                        run["proxy_s"].get<double>(), run["mvs_s"].get<double>());
  }
  text += fmt::format("  growth: whole run views^{:.2f}, proxy views^{:.2f}\n", time_exponent,
                      proxy_exponent);
  return text;
}

int Run(const RealBenchArgs& args) {
  const fs::path reference = args.reference.empty()
                                 ? fs::path(args.dataset) / "3d" / "romi_mesh.ply"
                                 : fs::path(args.reference);
  const bool own_work_dir = args.work_dir.empty();
  const fs::path work = own_work_dir
                            ? fs::temp_directory_path() / fmt::format("avc-bench-real-{}", getpid())
                            : fs::path(args.work_dir);
  fs::create_directories(work);

  nlohmann::json json;
  json["benchmark"] = "real";
  json["dataset"] = args.dataset;
  json["reference"] = reference.string();
  json["sets"] = args.sets;
  nlohmann::json runs = nlohmann::json::array();
  std::vector<double> views, walls, proxies;
  fs::path full_run;
  int fewest_stride = 1 << 30;
  for (int stride : args.strides) {
    const fs::path output = work / fmt::format("stride-{}", stride);
    nlohmann::json run = RunOne(args, stride, output);
    views.push_back(run["views"].get<double>());
    walls.push_back(run["wall_s"].get<double>());
    proxies.push_back(std::max(1e-3, run["proxy_s"].get<double>()));
    runs.push_back(run);
    if (stride < fewest_stride) {
      fewest_stride = stride;
      full_run = output;
    }
  }
  json["runs"] = runs;
  const double time_exponent = runs.size() > 1 ? PowerLawExponent(views, walls) : 0.0;
  const double proxy_exponent = runs.size() > 1 ? PowerLawExponent(views, proxies) : 0.0;
  json["time_exponent"] = time_exponent;
  json["proxy_exponent"] = proxy_exponent;

  std::cerr << "comparing with the reference ...\n";
  RealScanFigureOptions figure_options;
  figure_options.tolerance_px = args.tolerance_px;
  figure_options.stride = fewest_stride;
  json["figures"] = MeasureRealScan(args.dataset, full_run, reference, figure_options);
  std::cout << FormatRealScanFigures(json["figures"]) << "\n"
            << FormatRuns(runs, time_exponent, proxy_exponent);
  if (args.json) std::cout << json.dump() << "\n";
  if (own_work_dir) {
    std::error_code ignored;
    fs::remove_all(work, ignored);
  }
  return 0;
}

}  // namespace

int RunRealBenchmark(const std::vector<std::string>& args) {
  RealBenchArgs parsed;
  CLI::App app(
      "avc reconstruct on a real scan, measured against the scanner's own reconstruction: MVS "
      "points and mesh (precision/recall at 1, 2, 5 mm; area; pieces), masks per view (plant "
      "fraction, mask pixels off the reference, reference pixels covered), height and width, "
      "and wall time and peak memory at several numbers of views. Run from the repository's "
      "root (the shared data is ../shared/data).",
      "avc bench real");
  app.add_option("--dataset", parsed.dataset, "the scan (any layout avc reconstruct reads)")
      ->capture_default_str();
  app.add_option(
      "--reference", parsed.reference,
      "reference mesh in the dataset's frame and unit (default: DATASET/3d/romi_mesh.ply)");
  app.add_option("--strides", parsed.strides,
                 "runs with every Nth view; the smallest N is compared with the reference")
      ->capture_default_str();
  app.add_option("--tolerance-px", parsed.tolerance_px,
                 "mask figures: distance (px) within which mask and reference agree")
      ->capture_default_str();
  app.add_option("--set", parsed.sets,
                 "SECTION.FIELD=VALUE for avc reconstruct (repeatable), to measure a variant");
  app.add_option("--work-dir", parsed.work_dir, "keep the runs here (default: a temporary folder)");
  app.add_flag("--json", parsed.json, "print one JSON document last");
  if (auto code = ParseBenchmarkArguments(app, args)) return *code;
  return Run(parsed);
}

}  // namespace avc::bench
