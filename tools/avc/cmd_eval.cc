// avc eval: scores a reconstruction against a ground-truth mesh (and optionally a set of views
// for coverage), printing a summary and writing JSON / HTML / PNG reports.

#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "core/eval/eval_command.h"
#include "core/eval/report_text.h"
#include "tools/avc/commands.h"
#include "tools/avc/run_guarded.h"

namespace avc::cli {
namespace {

int RunEval(const eval::EvalCommandOptions& options, bool json_to_stdout) {
  const nlohmann::json report = eval::RunEvalCommand(options);
  std::cout << eval::FormatSummary(report);
  for (const auto& [what, path] : {std::pair{"JSON", options.json_output},
                                   {"HTML", options.html_output},
                                   {"plot", options.plot_output}}) {
    if (!path.empty()) std::cout << fmt::format("wrote {} {}\n", what, path.string());
  }
  if (json_to_stdout) std::cout << report.dump() << "\n";
  return 0;
}

}  // namespace

void RegisterEval(CLI::App& root, int* exit_code) {
  auto options = std::make_shared<eval::EvalCommandOptions>();
  auto json = std::make_shared<std::string>();
  CLI::App* command = root.add_subcommand(
      "eval",
      "Score a reconstruction (cloud or mesh) against a ground-truth mesh.\n"
      "Accuracy (reconstruction -> GT:\n"
      "RMSE, mean, median, 90th percentile), completeness (GT -> reconstruction), precision,\n"
      "recall and F-score at each threshold, area ratio (meshes), all per organ when the GT\n"
      "has face labels; with --cameras also the coverage of the GT surface by those views.\n"
      "A reconstruction mesh (.ply with faces, .obj, .off) is sampled uniformly by area; a\n"
      "point cloud (.ply without faces, .xyz as 'x y z [nx ny nz]' lines) is used point by\n"
      "point. Units are metres (--scale 0.001 for millimetre files). Areas are one-sided; a\n"
      "closed GT solid (e.g. the synthetic maize) counts both sides of a leaf.\n"
      "\n"
      "Cameras JSON (--cameras), as a scan directory's cameras.json:\n"
      "  {\"cameras\": [{\"name\": \"view_0000.png\", \"width\": 640, \"height\": 480,\n"
      "    \"fx\": 800, \"fy\": 800, \"cx\": 319.5, \"cy\": 239.5,\n"
      "    \"distortion\": [k1, k2, p1, p2, k3],   (optional, OpenCV order)\n"
      "    \"T_cam_world\": [16 numbers]}, ...]}   (world -> camera, metres, row-major 4x4)\n"
      "or the bare list. A GT sample is covered when at least --min-views cameras see\n"
      "it inside the image, unoccluded by the GT, at a grazing angle below --max-grazing-deg.\n"
      "\n"
      "Example: avc eval --gt plant.ply --reconstruction mesh.ply --html report.html");
  command->add_option("--gt", options->ground_truth, "ground-truth mesh (.ply, .obj, .off)")
      ->required();
  command
      ->add_option("--reconstruction", options->reconstruction,
                   "reconstruction: mesh (.ply, .obj, .off) or point cloud (.ply, .xyz)")
      ->required();
  command
      ->add_option("--thresholds", options->thresholds,
                   "comma-separated distance thresholds in metres")
      ->delimiter(',')
      ->capture_default_str();
  command
      ->add_option("--samples-per-m2", options->samples_per_m2,
                   "density of the area-uniform samples of the GT and of a reconstruction mesh")
      ->capture_default_str();
  command->add_option("--seed", options->seed, "seed of the samples")->capture_default_str();
  command
      ->add_option("--scale", options->scale,
                   "multiplies the coordinates of both files into metres (0.001 for mm)")
      ->capture_default_str();
  command->add_option("--json", *json, "write the report as JSON here ('-': print it last)");
  command->add_option("--html", options->html_output, "write a self-contained HTML report here");
  command->add_option("--plot", options->plot_output,
                      "write the error plot (distance histograms, scores) as PNG here");
  command->add_option("--cameras", options->cameras,
                      "cameras JSON (see above): also report coverage by these views");
  command
      ->add_option("--min-views", options->min_views, "views a GT sample needs to count as covered")
      ->capture_default_str();
  command
      ->add_option("--max-grazing-deg", options->max_grazing_deg,
                   "largest angle between surface normal (either side) and view direction")
      ->capture_default_str();
  SetGuardedRun(command, exit_code, [options, json] {
    const bool json_to_stdout = *json == "-";
    options->json_output = json_to_stdout ? std::filesystem::path() : std::filesystem::path(*json);
    return RunEval(*options, json_to_stdout);
  });
}

}  // namespace avc::cli
