#pragma once

// Reads a set of calibrated images from a directory, recognising its layout:
//  - a scan directory (ours, and what `avc sim render` writes): cameras.json, images/<name>,
//    optional gt_mesh.ply (the simulator's ground truth);
//  - a COLMAP text model: cameras.txt + images.txt in the directory, or in colmap/ or sparse/
//    (or sparse/0/); images in images/ or next to the model;
//  - a Middlebury multi-view set: one *_par.txt ("name K(9) R(9) t(3)" per line, P = K[R|t]),
//    images next to it.
// In every layout, masks/<image name> (any image format with the same name, or the same stem
// with .png) is read as that image's plant mask when present (non-zero = plant).
// Errors name the file and the entry at fault (std::runtime_error).

#include <filesystem>
#include <string>

#include "core/dataset/view.h"

namespace avc::dataset {

struct ReadOptions {
  bool load_masks = true;
  // Keep only every `stride`-th image (1 = all), for quick looks at large sets.
  int stride = 1;
};

// "scan", "colmap" or "middlebury" for a directory in one of those layouts; empty otherwise.
std::string DetectDatasetFormat(const std::filesystem::path& dir);

// Reads every view (in the camera file's order). Throws std::runtime_error when the directory
// is in no known layout, an image is missing or unreadable, or its size disagrees with its
// camera.
ViewSet ReadDataset(const std::filesystem::path& dir, const ReadOptions& options = {});

}  // namespace avc::dataset
