#pragma once

// A calibrated image as the reconstruction works on it: pixels, the camera that took them, and
// optionally which pixels are plant. Every importer (COLMAP text, Middlebury, scan directories)
// and the live builder produce these; segmentation fills `mask`, carving and MVS read it.

#include <Eigen/Core>
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
  std::string format;               // "colmap", "middlebury", "scan", "romi" or "live"
  // The unit the dataset's files are in (cameras are converted to metres on reading), and one
  // line saying how it was decided.
  std::string unit = "m";
  double metres_per_unit = 1.0;
  std::string unit_note;
  // The turn the import gave the world so that z is up (core/dataset/world_up.h): a point of the
  // dataset's files is at world_rotation * metres_per_unit * X in the views' world.
  Eigen::Matrix3d world_rotation = Eigen::Matrix3d::Identity();
  std::string orientation_note;  // empty when the world was not turned
  // Takes a point of the dataset's files (e.g. gt_mesh.ply) to the views' world.
  Eigen::Matrix3d FileToWorld() const { return metres_per_unit * world_rotation; }
  // A simulated scan's ground truth (gt_mesh.ply, in the dataset's unit), when the directory has
  // one; else empty.
  std::filesystem::path ground_truth_mesh;
};

}  // namespace avc::dataset
