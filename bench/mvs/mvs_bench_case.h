#pragma once

// One run of `avc bench mvs`: a dataset reconstructed with one MVS method at one pyramid level,
// measured (points, points per image, time) and scored (inside-silhouette fraction for the
// Middlebury set, precision / recall against the plant's ground truth for simulated scans).

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "services/builder/reconstruction.h"

namespace avc::bench {

struct MvsCase {
  std::string dataset_name;  // for the table: "dinoSparseRing", "rosette", ...
  std::filesystem::path dataset;
  builder::MvsMethod method = builder::MvsMethod::kPatch;
  int level = -1;  // -1: the method's automatic choice
  // Score against the Middlebury silhouette recipe (grey > 0.19, dilate 10, erode 7).
  bool silhouettes = false;
};

// Runs the case in this process and returns its figures: points, points_per_image, level,
// seconds (whole reconstruction), mvs_seconds, and inside_fraction or precision_1mm,
// recall_2mm, mean_distance_m. The ground truth is the dataset's gt_mesh.ply restricted to the
// plant's organs (stem, petioles, leaves): the masks leave the pot and soil out on purpose.
nlohmann::json RunMvsCase(const MvsCase& mvs_case);

}  // namespace avc::bench
