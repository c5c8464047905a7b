#pragma once

// A calibrated image as the reconstruction works on it: pixels, the camera that took them, and
// optionally which pixels are plant. Every importer (COLMAP text, Middlebury, scan directories)
// and the live builder produce these; segmentation fills `mask`, carving and MVS read it.

#include <filesystem>
#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

#include "core/camera/pinhole_camera.h"

namespace avc::dataset {

struct View {
  std::string name;       // image file name, unique within a set ("view_0003.png")
  camera::Camera camera;  // world -> camera; intrinsics size equals the image size
  cv::Mat image;          // CV_8UC3, BGR
  cv::Mat mask;           // empty, or CV_8UC1 of the image size: 255 plant, 0 background
};

struct ViewSet {
  std::vector<View> views;
  std::filesystem::path directory;  // where the set was read from (empty when built live)
  std::string format;               // "colmap", "middlebury", "scan" or "live"
  // A simulated scan's ground truth (gt_mesh.ply), when the directory has one; else empty.
  std::filesystem::path ground_truth_mesh;
};

}  // namespace avc::dataset
