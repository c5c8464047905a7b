#pragma once

// The ROMI plant scanner's scan layout (romi/plant-3d-explorer): index.json with
//   camera.params = [fx, fy, cx, cy, k1, k2, p1, p2] (OpenCV), shared by every view;
//   camera.poses[i] = {rotmat: R (3x3 rows), tvec: t, photoUri: ".../<image file>"}, world to
//   camera (x_cam = R X + t), in millimetres;
// and the photographs in undist/, already undistorted, so the cameras are pinholes. The views
// are returned in image-name order (the poses list them in the reverse order).

#include <filesystem>
#include <vector>

#include "core/camera/camera_io.h"

namespace avc::dataset {

// True when dir/index.json exists and has camera.poses.
bool IsRomiScan(const std::filesystem::path& dir);

// Cameras with width = height = 0 (the image's own size is taken). Throws std::runtime_error
// naming index.json and the entry at fault.
std::vector<camera::NamedCamera> ReadRomiIndex(const std::filesystem::path& index_json);

}  // namespace avc::dataset
