#pragma once

// The plant proxy part of `avc bench mvs`: a simulated scan carved at a fixed voxel size (the
// issue's 2 mm) from its automatic masks, timed, and compared voxel by voxel with the plant's
// ground-truth surface voxelised on the proxy's grid.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace avc::bench {

struct PprCase {
  std::string dataset_name;
  std::filesystem::path dataset;
  double voxel_size = 0.002;
};

// Figures: views, voxel_size_m, occupied, bounds_seconds (the automatic box's coarse pass),
// carve_seconds (every view carved at the coarse level, then the resolution increase to the
// final voxel size), iou, voxel_precision, voxel_recall, truth_voxels; for a simulated scan
// with label images also ideal_occupied, ideal_iou (the same carving from perfect masks against
// the surface) and iou_with_ideal (our proxy against that one).
nlohmann::json RunPprCase(const PprCase& ppr_case);

}  // namespace avc::bench
