#pragma once

// One plant of `avc bench nbv`: the planner runs Algorithm 1 in the simulated cell (rendered
// captures, automatic masks), the baselines take their views around the same framed plant, and
// every view set is scored by the coverage of the plant's ground-truth surface (seen by >= 3
// views at a grazing angle under 75 degrees, occlusion included; eval/coverage.h).

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "services/planner/active_vision.h"

namespace avc::bench {

struct NbvCase {
  std::string plant;                // a preset name, or a label for mesh_file
  std::filesystem::path mesh_file;  // non-empty: this mesh instead of a preset
  double render_scale = 0.5;
  int baseline_views = 40;
  uint64_t seed = 1;
  // Also run the builder on every view set but the ceiling (the paper's Table 1).
  bool build = false;
  // Captures the planner may take (Phase 1 and 2) before Phase 3 removes redundant ones.
  int capture_budget = planner::ActiveVisionOptions{}.max_views;
  // Phase 3's limit on the covered proxy faces lost (ActiveVisionOptions).
  double prune_face_loss = planner::ActiveVisionOptions{}.prune_max_covered_faces_lost;
  std::vector<double> elevations_deg;  // Phase 1's heights; empty: the planner's
};

// Figures: per method (ours, orbit 3x10, one static, two static, random, the sphere ceiling, the
// sphere's views chosen greedily on the ground truth at our image count, at 10 % fewer than
// baseline_views and at baseline_views, the same over spheres at 0.6, 0.8 and 1 times the distance,
// information gain at our image count) the images, coverage,
// coverage after 10/20/30 images and images to 90 %; ours also captured, planning seconds per
// next-best-view iteration (median, max), patches, failing patches and notes; with `build`, each
// set's points, points per image and their mean distance to the plant (view_set_build.h).
nlohmann::json RunNbvCase(const NbvCase& nbv_case);

}  // namespace avc::bench
