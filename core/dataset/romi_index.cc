#include "core/dataset/romi_index.h"

#include <fmt/format.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/dataset/exact_pose.h"
#include "core/util/json_file.h"

namespace avc::dataset {
namespace fs = std::filesystem;
namespace {

Eigen::Matrix3d ReadRotation(const nlohmann::json& rows) {
  if (!rows.is_array() || rows.size() != 3) throw std::runtime_error("rotmat must be 3 rows");
  Eigen::Matrix3d r;
  for (int i = 0; i < 3; ++i) {
    if (!rows[i].is_array() || rows[i].size() != 3) {
      throw std::runtime_error("rotmat rows must hold 3 numbers");
    }
    for (int j = 0; j < 3; ++j) r(i, j) = rows[i][j].get<double>();
  }
  return r;
}

camera::NamedCamera ReadPose(const nlohmann::json& pose, const camera::Intrinsics& intrinsics) {
  const nlohmann::json& t = pose.at("tvec");
  if (!t.is_array() || t.size() != 3) throw std::runtime_error("tvec must hold 3 numbers");
  const auto exact = ExactPose(ReadRotation(pose.at("rotmat")),
                               {t[0].get<double>(), t[1].get<double>(), t[2].get<double>()});
  if (!exact) throw std::runtime_error("rotmat is not a rotation, or a number is not finite");
  camera::NamedCamera named;
  named.name = fs::path(pose.at("photoUri").get<std::string>()).filename().string();
  if (named.name.empty()) throw std::runtime_error("photoUri names no file");
  named.camera.intrinsics = intrinsics;
  named.camera.T_cam_world = *exact;
  return named;
}

}  // namespace

bool IsRomiScan(const fs::path& dir) {
  if (!fs::is_regular_file(dir / "index.json")) return false;
  try {
    const nlohmann::json json = ReadJsonFile(dir / "index.json");
    return json.contains("camera") && json["camera"].contains("poses");
  } catch (const std::exception&) {
    return false;
  }
}

std::vector<camera::NamedCamera> ReadRomiIndex(const fs::path& index_json) {
  const nlohmann::json json = ReadJsonFile(index_json);
  const auto fail = [&](const std::string& what) {
    throw std::runtime_error(fmt::format("{}: {}", index_json.string(), what));
  };
  if (!json.contains("camera") || !json["camera"].contains("params") ||
      !json["camera"].contains("poses")) {
    fail("no camera.params and camera.poses");
  }
  const nlohmann::json& params = json["camera"]["params"];
  if (!params.is_array() || params.size() < 4) fail("camera.params must start with fx fy cx cy");
  camera::Intrinsics intrinsics;
  try {
    intrinsics.fx = params[0].get<double>();
    intrinsics.fy = params[1].get<double>();
    intrinsics.cx = params[2].get<double>();
    intrinsics.cy = params[3].get<double>();
  } catch (const nlohmann::json::exception&) {
    fail("camera.params must be numbers");
  }
  std::vector<camera::NamedCamera> cameras;
  const nlohmann::json& poses = json["camera"]["poses"];
  if (!poses.is_array()) fail("camera.poses must be a list");
  for (size_t i = 0; i < poses.size(); ++i) {
    try {
      cameras.push_back(ReadPose(poses[i], intrinsics));
    } catch (const std::exception& error) {
      fail(fmt::format("camera.poses[{}]: {}", i, error.what()));
    }
  }
  std::sort(cameras.begin(), cameras.end(),
            [](const auto& a, const auto& b) { return a.name < b.name; });
  for (size_t i = 1; i < cameras.size(); ++i) {
    if (cameras[i].name == cameras[i - 1].name) {
      fail(fmt::format("two poses name the image '{}'", cameras[i].name));
    }
  }
  return cameras;
}

}  // namespace avc::dataset
