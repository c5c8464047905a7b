#pragma once

// Camera sets on disk, in the two formats a scan directory carries:
//  - cameras.json: {"cameras": [{"name", "width", "height", "fx", "fy", "cx", "cy",
//    "distortion": [k1, k2, p1, p2, k3], "T_cam_world": 16 numbers, row-major 4x4}]};
//  - a COLMAP text model (cameras.txt, images.txt, empty points3D.txt) that COLMAP, OpenMVS and
//    most MVS tools read. Cameras use COLMAP's OPENCV model (fx fy cx cy k1 k2 p1 p2), or
//    FULL_OPENCV when k3 is not zero.
// Readers throw std::runtime_error naming the file and line or entry of any problem.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/camera/pinhole_camera.h"

namespace avc::camera {

struct NamedCamera {
  std::string name;  // the image file name, relative to the images folder
  Camera camera;
};

// One cameras.json entry. Throws std::invalid_argument for an unusable camera.
nlohmann::ordered_json CameraToJson(const NamedCamera& camera);

// One cameras.json entry back (name defaults to default_name). Throws std::runtime_error saying
// what is wrong with it.
NamedCamera CameraFromJson(const nlohmann::json& entry, const std::string& default_name);

void WriteCamerasJson(const std::filesystem::path& path, const std::vector<NamedCamera>& cameras);
std::vector<NamedCamera> ReadCamerasJson(const std::filesystem::path& path);

// Writes cameras.txt, images.txt and points3D.txt into dir (created). Views sharing identical
// intrinsics share one COLMAP camera.
void WriteColmapText(const std::filesystem::path& dir, const std::vector<NamedCamera>& cameras);
std::vector<NamedCamera> ReadColmapText(const std::filesystem::path& dir);

}  // namespace avc::camera
