#include "bench/render/render_bench.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <thread>

#include "bench/registry.h"
#include "bench/render/render_bench_case.h"
#include "sim/render/renderer.h"
#include "sim/scene/plant.h"

namespace avc::bench {
namespace {

namespace fs = std::filesystem;

// Goal of the renderer issue: a 1280x960 frame of a 100k-triangle plant in under 150 ms on 2
// cores with the default options.
constexpr double kGoalMs = 150.0;

struct RenderBenchArgs {
  int views = 12;
  int width = 1280, height = 960;
  int plant_triangles = 40000;
  int big_triangles = 100000;
  std::string big_preset = "broadleaf";
  uint32_t seed = 1;
  std::string save_dir;
  bool json = false;
};

sim::RenderOptions BenchOptions(int samples) {
  sim::RenderOptions options;
  options.samples_per_pixel_axis = samples;
  options.background.kind = sim::Background::Kind::kCloth;
  return options;
}

RenderCaseSpec Spec(const RenderBenchArgs& args, std::string name, int samples, int threads,
                    int scale_down = 1) {
  RenderCaseSpec spec;
  spec.name = std::move(name);
  spec.width = args.width / scale_down;
  spec.height = args.height / scale_down;
  spec.views = args.views;
  spec.threads = threads;
  spec.options = BenchOptions(samples);
  return spec;
}

// Colour, labels (false colour) and depth of the first view, for looking at.
void SaveFirstView(const sim::Scene& scene, const RenderCaseSpec& spec, const fs::path& dir,
                   const std::string& stem) {
  fs::create_directories(dir);
  const camera::Camera camera = ViewsAround(scene, BenchIntrinsics(spec.width, spec.height), 1)[0];
  const sim::RenderResult frame = sim::Render(scene, camera, spec.options);
  cv::imwrite((dir / (stem + "-color.png")).string(), frame.color);
  cv::Mat labels(frame.labels.size(), CV_8UC3);
  for (int v = 0; v < labels.rows; ++v) {
    for (int u = 0; u < labels.cols; ++u) {
      const uint32_t l = static_cast<uint32_t>(frame.labels.at<int32_t>(v, u)) * 2654435761u;
      labels.at<cv::Vec3b>(v, u) = frame.labels.at<int32_t>(v, u) == 0
                                       ? cv::Vec3b(0, 0, 0)
                                       : cv::Vec3b(l & 255, (l >> 8) & 255, (l >> 16) & 255);
    }
  }
  cv::imwrite((dir / (stem + "-labels.png")).string(), labels);
  double lo = 0, hi = 0;
  cv::minMaxLoc(frame.depth, &lo, &hi, nullptr, nullptr, frame.labels != 0);
  cv::Mat depth;
  frame.depth.convertTo(depth, CV_8U, 255.0 / std::max(hi - lo, 1e-6),
                        -lo * 255.0 / std::max(hi - lo, 1e-6));
  depth.setTo(0, frame.labels == 0);
  cv::imwrite((dir / (stem + "-depth.png")).string(), depth);
}

void PrintTable(const std::vector<RenderCaseResult>& results) {
  std::cout << fmt::format(
      "{:<24} {:>9} {:>9} {:>9} {:>6} {:>3} {:>3} {:>9} {:>9} {:>9} {:>9} {:>8}\n", "case", "size",
      "triangles", "raster", "cover", "spp", "thr", "median", "p90", "max", "cpu/frame",
      "peak RSS");
  for (const RenderCaseResult& r : results) {
    std::cout << fmt::format(
        "{:<24} {:>9} {:>9} {:>9} {:>5.0f}% {:>3} {:>3} {:>7.1f}ms {:>7.1f}ms {:>7.1f}ms "
        "{:>7.1f}ms {:>6.0f}MB\n",
        r.spec.name, fmt::format("{}x{}", r.spec.width, r.spec.height), r.triangles,
        r.raster_triangles, 100 * r.coverage, r.spec.options.samples_per_pixel_axis, r.spec.threads,
        r.median_ms, r.p90_ms, r.max_ms, r.cpu_ms_per_frame, r.max_rss_mb);
  }
}

const RenderCaseResult& Find(const std::vector<RenderCaseResult>& results,
                             const std::string& name) {
  for (const RenderCaseResult& r : results) {
    if (r.spec.name == name) return r;
  }
  throw std::logic_error("no bench case " + name);
}

nlohmann::json ToJson(const RenderBenchArgs& args, const std::vector<RenderCaseResult>& results,
                      const nlohmann::json& ratios, bool goal) {
  nlohmann::json json;
  json["benchmark"] = "render";
  json["views"] = args.views;
  json["seed"] = args.seed;
  double load[3] = {0, 0, 0};
  json["load_average_1min"] = getloadavg(load, 3) >= 1 ? load[0] : -1.0;
  json["goal_ms"] = kGoalMs;
  json["goal_met"] = goal;
  json["ratios"] = ratios;
  for (const RenderCaseResult& r : results) {
    json["cases"].push_back({{"name", r.spec.name},
                             {"width", r.spec.width},
                             {"height", r.spec.height},
                             {"triangles", r.triangles},
                             {"raster_triangles", r.raster_triangles},
                             {"coverage", r.coverage},
                             {"samples_per_pixel_axis", r.spec.options.samples_per_pixel_axis},
                             {"threads", r.spec.threads},
                             {"median_ms", r.median_ms},
                             {"p90_ms", r.p90_ms},
                             {"max_ms", r.max_ms},
                             {"cpu_ms_per_frame", r.cpu_ms_per_frame},
                             {"peak_rss_mb", r.max_rss_mb}});
  }
  return json;
}

int Run(const RenderBenchArgs& args) {
  std::vector<RenderCaseResult> results;
  auto run = [&](const sim::Scene& scene, const RenderCaseSpec& spec) {
    std::cerr << "  " << spec.name << "...\n";
    results.push_back(RunRenderCase(scene, spec));
  };

  sim::PlantOptions big_options;
  big_options.target_triangles = args.big_triangles;
  const sim::PlantPreset big_preset = sim::ParsePreset(args.big_preset);
  const sim::Scene big = sim::GeneratePlant(big_preset, args.seed, big_options);
  // Size scaling first (1x, 4x, then 16x below), so peak memory shows its growth.
  run(big, Spec(args, "big/quarter-size", 2, 2, 4));
  run(big, Spec(args, "big/half-size", 2, 2, 2));
  run(big, Spec(args, "big", 2, 2));
  run(big, Spec(args, "big/1-sample", 1, 2));
  run(big, Spec(args, "big/3x3-samples", 3, 2));
  run(big, Spec(args, "big/1-thread", 2, 1));
  for (sim::PlantPreset preset : sim::AllPresets()) {
    sim::PlantOptions options;
    options.target_triangles = args.plant_triangles;
    const sim::Scene plant = sim::GeneratePlant(preset, args.seed, options);
    const RenderCaseSpec spec = Spec(args, fmt::format("preset/{}", sim::PresetName(preset)), 2, 2);
    run(plant, spec);
    if (!args.save_dir.empty())
      SaveFirstView(plant, spec, args.save_dir, std::string(sim::PresetName(preset)));
  }
  if (!args.save_dir.empty()) SaveFirstView(big, Spec(args, "big", 2, 2), args.save_dir, "big");

  double load[3] = {0, 0, 0};
  if (getloadavg(load, 3) < 1) load[0] = -1;
  std::cout << fmt::format(
      "avc bench render: {} views per case around each plant (seed {}), cloth background, lens "
      "k1=-0.08 k2=0.03; {} cores, 1-min load average {:.2f} at the end (other work inflates "
      "times)\n",
      args.views, args.seed, std::thread::hardware_concurrency(), load[0]);
  std::cout << fmt::format("big = {} preset at {} target triangles\n", args.big_preset,
                           args.big_triangles);
  PrintTable(results);
  const RenderCaseResult& main = Find(results, "big");
  nlohmann::json ratios = {
      {"time_1_sample_over_2x2", Find(results, "big/1-sample").median_ms / main.median_ms},
      {"time_3x3_over_2x2", Find(results, "big/3x3-samples").median_ms / main.median_ms},
      {"speedup_2_threads_over_1", Find(results, "big/1-thread").median_ms / main.median_ms},
      {"time_4x_pixels_over_1x",
       Find(results, "big/half-size").median_ms / Find(results, "big/quarter-size").median_ms},
      {"time_16x_pixels_over_1x", main.median_ms / Find(results, "big/quarter-size").median_ms}};
  std::cout << fmt::format(
      "ratios (median times): 1x1/2x2 samples {:.2f}, 3x3/2x2 {:.2f}, 2 threads speed-up {:.2f}, "
      "pixels 4x {:.2f}, 16x {:.2f}\n",
      ratios["time_1_sample_over_2x2"].get<double>(), ratios["time_3x3_over_2x2"].get<double>(),
      ratios["speedup_2_threads_over_1"].get<double>(),
      ratios["time_4x_pixels_over_1x"].get<double>(),
      ratios["time_16x_pixels_over_1x"].get<double>());
  const bool goal = main.median_ms < kGoalMs;
  std::cout << fmt::format(
      "goal ({} triangles, {}x{}, 2x2 samples, 2 threads: median < {:.0f} ms): {}\n",
      main.triangles, main.spec.width, main.spec.height, kGoalMs, goal ? "met" : "NOT met");
  if (args.json) std::cout << ToJson(args, results, ratios, goal).dump() << "\n";
  return goal ? 0 : 1;
}

}  // namespace

int RunRenderBenchmark(const std::vector<std::string>& arguments) {
  RenderBenchArgs args;
  CLI::App app{
      "avc bench render: frame time of the CPU renderer on views around each plant preset and a\n"
      "100k-triangle plant, with 1/2x2/3x3 samples, 1 vs 2 threads and 1x/4x/16x pixels.",
      "avc bench render"};
  app.add_option("--views", args.views, "views (frames) per case")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  app.add_option("--width", args.width, "image width of the full-size cases")
      ->capture_default_str()
      ->check(CLI::Range(64, 8192));
  app.add_option("--height", args.height, "image height of the full-size cases")
      ->capture_default_str()
      ->check(CLI::Range(48, 8192));
  app.add_option("--plant-triangles", args.plant_triangles, "target triangles of the preset plants")
      ->capture_default_str()
      ->check(CLI::Range(100, 10'000'000));
  app.add_option("--big-triangles", args.big_triangles, "target triangles of the big plant")
      ->capture_default_str()
      ->check(CLI::Range(100, 10'000'000));
  app.add_option("--big-preset", args.big_preset, "preset of the big plant")
      ->capture_default_str()
      ->check(CLI::IsMember({"rosette", "broadleaf", "strap", "bushy"}));
  app.add_option("--seed", args.seed, "plant seed")->capture_default_str();
  app.add_option("--save", args.save_dir, "write colour, label and depth PNGs of a view per plant");
  app.add_flag("--json", args.json, "print the results as one JSON line at the end");
  if (const auto exit_code = ParseBenchmarkArguments(app, arguments)) return *exit_code;
  return Run(args);
}

}  // namespace avc::bench
