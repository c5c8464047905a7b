#include "bench/nbv/nbv_case.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "bench/mvs/plant_organs.h"
#include "bench/nbv/baseline_views.h"
#include "bench/nbv/information_gain.h"
#include "bench/nbv/simulated_capture.h"
#include "bench/nbv/view_set_build.h"
#include "bench/summary.h"
#include "core/eval/coverage.h"
#include "core/eval/coverage_oracle.h"
#include "services/planner/active_vision.h"
#include "sim/dataset/render_dataset.h"

namespace avc::bench {
namespace {

constexpr double kDegree = M_PI / 180;

// Per camera, the samples it sees.
std::vector<std::vector<uint8_t>> SeenByEach(const eval::CoverageModel& model,
                                             const std::vector<camera::Camera>& cameras) {
  std::vector<std::vector<uint8_t>> seen;
  for (const camera::Camera& camera : cameras) seen.push_back(model.SeenBy(camera));
  return seen;
}

// Coverage of the first 1, 2, ... views: curve[n - 1] after n.
std::vector<double> CoverageCurve(const std::vector<std::vector<uint8_t>>& seen_by_each,
                                  size_t samples, int min_views) {
  std::vector<int> counts(samples, 0);
  std::vector<double> curve;
  size_t covered = 0;
  for (const std::vector<uint8_t>& seen : seen_by_each) {
    for (size_t s = 0; s < seen.size(); ++s) {
      if (seen[s] && ++counts[s] == min_views) ++covered;
    }
    curve.push_back(counts.empty() ? 0.0 : static_cast<double>(covered) / counts.size());
  }
  return curve;
}

nlohmann::json CurveJson(const std::string& name, const std::vector<double>& curve) {
  nlohmann::json json = {
      {"method", name}, {"images", curve.size()}, {"coverage", curve.empty() ? 0.0 : curve.back()}};
  for (const int n : {10, 20, 30}) {
    if (static_cast<int>(curve.size()) >= n) json[fmt::format("after_{}", n)] = curve[n - 1];
  }
  const auto reach = std::find_if(curve.begin(), curve.end(), [](double c) { return c >= 0.9; });
  if (reach != curve.end()) json["images_to_90"] = reach - curve.begin() + 1;
  return json;
}

nlohmann::json MethodJson(const std::string& name, const eval::CoverageModel& model,
                          const std::vector<camera::Camera>& cameras) {
  return CurveJson(name, CoverageCurve(SeenByEach(model, cameras), model.samples().size(),
                                       model.options().min_views));
}

// The sphere's views a planner that knew the ground truth would take (eval/coverage_oracle.h):
// the coverage n views of the sphere allow, for n = each count in `counts`.
std::vector<nlohmann::json> OracleJson(const std::vector<std::vector<uint8_t>>& sphere_seen,
                                       int min_views, const std::vector<int>& counts,
                                       const std::string& label) {
  const int most = *std::max_element(counts.begin(), counts.end());
  const eval::OracleSelection oracle = eval::GreedyCoverageSelection(sphere_seen, min_views, most);
  std::vector<nlohmann::json> methods;
  for (const int n : counts) {
    // The oracle stops early when no view adds coverage: its curve is flat from there.
    std::vector<double> curve(
        oracle.coverage.begin(),
        oracle.coverage.begin() + std::min<size_t>(n, oracle.coverage.size()));
    methods.push_back(CurveJson(fmt::format("ground-truth greedy{} ({})", label, n), curve));
  }
  return methods;
}

std::vector<camera::Camera> Cameras(const std::vector<planner::CellView>& views) {
  std::vector<camera::Camera> cameras;
  for (const planner::CellView& v : views) cameras.push_back(v.camera);
  return cameras;
}

}  // namespace

nlohmann::json RunNbvCase(const NbvCase& nbv_case) {
  sim::RenderDatasetOptions scene_options;
  if (nbv_case.mesh_file.empty()) {
    scene_options.preset = sim::ParsePreset(nbv_case.plant);
  } else {
    scene_options.mesh_file = nbv_case.mesh_file;
  }
  const sim::Scene scene = sim::MakeScene(scene_options);
  const sim::CellTruth cell = sim::MakeCell(scene_options);
  const geometry::Mesh organs = PlantOrgans(scene.mesh);
  const eval::CoverageModel model(organs, 2e5, nbv_case.seed);
  const auto method = [&](const std::string& name, const std::vector<camera::Camera>& cameras,
                          bool build) {
    nlohmann::json json = MethodJson(name, model, cameras);
    if (build && nbv_case.build) {
      std::cerr << "  building " << name << " (" << cameras.size() << " images)\n";
      json.update(BuildViewSet(scene, cameras, nbv_case.render_scale, organs));
    }
    return json;
  };

  SimulatedCapture capture(scene, nbv_case.render_scale);
  planner::ActiveVisionOptions planner_options;
  planner_options.max_views = nbv_case.capture_budget;
  planner_options.prune_max_covered_faces_lost = nbv_case.prune_face_loss;
  if (!nbv_case.elevations_deg.empty()) planner_options.elevations_deg = nbv_case.elevations_deg;
  const planner::ActiveVisionResult ours = planner::RunActiveVision(
      cell, [&](const planner::CellView& view) { return capture(view); }, planner_options);

  std::vector<camera::Camera> kept, initial, captured;
  for (const planner::PlannedView& v : ours.views) {
    captured.push_back(v.view.camera);
    if (v.kept) kept.push_back(v.view.camera);
    if (v.phase == "initial") initial.push_back(v.view.camera);
  }
  nlohmann::json methods = nlohmann::json::array();
  nlohmann::json our_json = method("ours (Algorithm 1)", kept, true);
  our_json["captured"] = ours.views.size();
  our_json["patches"] = ours.patches;
  our_json["failing_patches"] = ours.failing_patches;
  if (!ours.iteration_seconds.empty()) {
    const Summary planning = Summarize(ours.iteration_seconds);
    our_json["planning_s_median"] = planning.median;
    our_json["planning_s_max"] = planning.max;
    our_json["iterations"] = planning.count;
    our_json["planning_s_per_view"] = ours.planning_seconds_per_view;
  }
  our_json["notes"] = ours.notes;
  methods.push_back(our_json);
  methods.push_back(method("ours before Phase 3", captured, false));
  methods.push_back(method("orbit 3x10 (Phase 1 alone)", initial, true));

  // The baselines around the same framed plant: the middle height's distance and the aim.
  planner::BaselineFrame frame;
  frame.aim = ours.aim;
  frame.distance =
      ours.framed_distances.empty() ? 0.5 : ours.framed_distances[ours.framed_distances.size() / 2];
  const int n = nbv_case.baseline_views;
  methods.push_back(method(fmt::format("one static camera ({})", n),
                           Cameras(planner::StaticCameraViews(cell, frame, 30 * kDegree, n)),
                           true));
  methods.push_back(method(
      fmt::format("two static cameras ({})", n),
      Cameras(planner::TwoStaticCameraViews(cell, frame, 10 * kDegree, 60 * kDegree, n)), true));
  methods.push_back(method(fmt::format("random reachable ({})", n),
                           Cameras(planner::RandomViews(cell, frame, n, nbv_case.seed)), true));
  // The ceiling: every reachable view of a dense sphere (5 to 85 degrees in 10 degree steps).
  std::vector<double> dense_elevations;
  for (int e = 5; e <= 85; e += 10) dense_elevations.push_back(e * kDegree);
  const std::vector<planner::CellView> sphere =
      planner::SphereViews(cell, frame, dense_elevations, 24);
  // Each sphere view's samples, once for both the ceiling and the ground-truth greedy rows.
  const std::vector<std::vector<uint8_t>> sphere_seen = SeenByEach(model, Cameras(sphere));
  const int min_views = model.options().min_views;
  methods.push_back(CurveJson(fmt::format("all sphere views ({}, ceiling)", sphere.size()),
                              CoverageCurve(sphere_seen, model.samples().size(), min_views)));
  // At our count, at 10 % fewer than the baselines' (the acceptance's fewest savings) and at
  // theirs.
  std::vector<int> oracle_counts = {static_cast<int>(kept.size()), n - n / 10, n};
  std::sort(oracle_counts.begin(), oracle_counts.end());
  oracle_counts.erase(std::unique(oracle_counts.begin(), oracle_counts.end()), oracle_counts.end());
  for (nlohmann::json& oracle : OracleJson(sphere_seen, min_views, oracle_counts, "")) {
    methods.push_back(std::move(oracle));
  }
  // The same on spheres at 0.6 and 0.8 of the distance as well: a closer camera reaches higher
  // elevations and sees a patch from nearer, as the planner's Phase 2 views do.
  std::vector<std::vector<uint8_t>> shells_seen = sphere_seen;
  for (const double factor : {0.6, 0.8}) {
    planner::BaselineFrame closer = frame;
    closer.distance *= factor;
    for (std::vector<uint8_t>& seen :
         SeenByEach(model, Cameras(planner::SphereViews(cell, closer, dense_elevations, 24)))) {
      shells_seen.push_back(std::move(seen));
    }
  }
  for (nlohmann::json& oracle :
       OracleJson(shells_seen, min_views, oracle_counts, ", 3 distances")) {
    methods.push_back(std::move(oracle));
  }
  // At our image count, on the proxy box our run found.
  const int ours_count = static_cast<int>(kept.size());
  methods.push_back(method(fmt::format("information gain ({})", ours_count),
                           Cameras(planner::InformationGainViews(
                               cell, [&](const planner::CellView& view) { return capture(view); },
                               ours.proxy->box(), frame.aim, frame.distance, ours_count)),
                           true));
  return {{"plant", nbv_case.plant},
          {"samples", model.samples().size()},
          {"renders", capture.captures()},
          {"methods", methods}};
}

}  // namespace avc::bench
