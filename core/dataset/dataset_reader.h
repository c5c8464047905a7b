#pragma once

// Reads a set of calibrated images from a directory, recognising its layout:
//  - a scan directory (ours, and what `avc sim render` writes): cameras.json, images/<name>,
//    optional gt_mesh.ply (the simulator's ground truth);
//  - a COLMAP text model: cameras.txt + images.txt in the directory, or in colmap/ or sparse/
//    (or sparse/0/); images in images/ or next to the model;
//  - a Middlebury multi-view set: one *_par.txt ("name K(9) R(9) t(3)" per line, P = K[R|t]),
//    images next to it;
//  - a ROMI plant scanner scan: index.json + undist/ (core/dataset/romi_index.h), millimetres.
// Lengths come out in metres: the dataset's unit (ReadOptions.units, else what the dataset
// declares: cameras.json's "units", "mm" for ROMI scans; else chosen from the cameras'
// distances, core/dataset/length_unit.h) is converted once, here, and a world whose up is not +z
// is turned so that it is (core/dataset/world_up.h).
// In every layout, masks/<image name> (any image format with the same name, or the same stem
// with .png) is read as that image's plant mask when present (non-zero = plant).
// Errors name the file and the entry at fault (std::runtime_error).

#include <filesystem>
#include <string>

#include "core/dataset/length_unit.h"
#include "core/dataset/view.h"

namespace avc::dataset {

struct ReadOptions {
  bool load_masks = true;
  // Keep only every `stride`-th image (1 = all), for quick looks at large sets.
  int stride = 1;
  // The dataset's length unit; kAuto = the one it declares, else chosen from its cameras.
  LengthUnit units = LengthUnit::kAuto;
  // Turn the world so that z is up when the cameras say another axis is (world_up.h).
  bool upright = true;
};

// "scan", "colmap", "middlebury" or "romi" for a directory in one of those layouts; empty
// otherwise.
std::string DetectDatasetFormat(const std::filesystem::path& dir);

// Reads every view (in the camera file's order). Throws std::runtime_error when the directory
// is in no known layout, an image is missing or unreadable, or its size disagrees with its
// camera, or its length unit is given wrongly or cannot be told.
ViewSet ReadDataset(const std::filesystem::path& dir, const ReadOptions& options = {});

}  // namespace avc::dataset
