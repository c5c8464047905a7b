#include "report/report_scene.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>

#include "report/report_encode.h"

namespace avc::report {
namespace {

std::string Bytes(const std::vector<std::array<uint8_t, 3>>& rgb) {
  std::vector<uint8_t> bytes;
  bytes.reserve(rgb.size() * 3);
  for (const auto& c : rgb) bytes.insert(bytes.end(), c.begin(), c.end());
  return Base64Encode(bytes);
}

std::string Bytes(const std::vector<Eigen::Matrix<uint8_t, 3, 1>>& rgb) {
  std::vector<std::array<uint8_t, 3>> flat(rgb.size());
  for (size_t i = 0; i < rgb.size(); ++i) flat[i] = {rgb[i][0], rgb[i][1], rgb[i][2]};
  return Bytes(flat);
}

nlohmann::ordered_json MeshJson(const geometry::Mesh& mesh) {
  std::vector<float> positions;
  positions.reserve(mesh.num_vertices() * 3);
  for (const Eigen::Vector3f& v : mesh.vertices)
    positions.insert(positions.end(), {v.x(), v.y(), v.z()});
  std::vector<int32_t> indices;
  indices.reserve(mesh.num_faces() * 3);
  for (const Eigen::Vector3i& f : mesh.faces) indices.insert(indices.end(), {f[0], f[1], f[2]});
  nlohmann::ordered_json json = {{"positions", Base64Floats(positions)},
                                 {"indices", Base64Ints(indices)},
                                 {"face_rgb", Bytes(FaceClusterColours(mesh))}};
  if (!mesh.colors.empty()) json["vertex_rgb"] = Bytes(mesh.colors);
  return json;
}

nlohmann::ordered_json PointsJson(const geometry::PointCloud& cloud) {
  const size_t stride = std::max<size_t>(1, (cloud.size() + kMaxPagePoints - 1) / kMaxPagePoints);
  std::vector<float> positions;
  std::vector<std::array<uint8_t, 3>> rgb;
  for (size_t i = 0; i < cloud.size(); i += stride) {
    const Eigen::Vector3f& p = cloud.positions[i];
    positions.insert(positions.end(), {p.x(), p.y(), p.z()});
    if (cloud.colors.empty()) {
      rgb.push_back({90, 140, 60});
    } else {
      rgb.push_back({cloud.colors[i][0], cloud.colors[i][1], cloud.colors[i][2]});
    }
  }
  return {{"count", cloud.size()},
          {"shown", positions.size() / 3},
          {"positions", Base64Floats(positions)},
          {"rgb", Bytes(rgb)}};
}

// The capture phase of each image file name, to colour the cameras by why they were taken.
std::map<std::string, std::string> PhasesByImage(const ReportInputs& in) {
  std::map<std::string, std::string> phases;
  if (!in.scan) return phases;
  for (const orchestrator::CaptureRecord& c : in.scan->captures) {
    phases[std::filesystem::path(c.file).filename().string()] = c.phase;
  }
  return phases;
}

std::string PhaseColour(const std::string& phase) {
  if (phase == "frame") return "#888888";
  if (phase == "initial") return "#2f6fd0";
  if (phase == "active") return "#e07020";
  return "#303030";
}

// Centre and image corners at a depth that keeps the frustum small next to the plant: a tenth of
// the camera's distance to it.
nlohmann::ordered_json CameraJson(const camera::NamedCamera& named, const Eigen::Vector3d& centre,
                                  const std::string& phase) {
  const camera::Camera& cam = named.camera;
  const camera::Intrinsics& k = cam.intrinsics;
  const Eigen::Isometry3d T_world_cam = cam.T_cam_world.inverse();
  const double depth = 0.1 * (cam.Centre() - centre).norm();
  std::vector<double> corners;
  auto add = [&](const Eigen::Vector3d& p) {
    corners.insert(corners.end(), {p.x(), p.y(), p.z()});
  };
  add(cam.Centre());
  const double w = k.width, h = k.height;
  for (const auto& [u, v] : {std::pair{0.0, 0.0}, {w, 0.0}, {w, h}, {0.0, h}}) {
    const Eigen::Vector3d ray((u - k.cx) / k.fx, (v - k.cy) / k.fy, 1.0);
    add(T_world_cam * (ray * depth));
  }
  return {{"name", named.name}, {"colour", PhaseColour(phase)}, {"corners", corners}};
}

}  // namespace

std::vector<std::array<uint8_t, 3>> FaceClusterColours(const geometry::Mesh& mesh) {
  std::vector<std::array<uint8_t, 3>> colours(mesh.num_faces(), ClusterColour(-1));
  for (size_t f = 0; f < mesh.face_labels.size(); ++f)
    colours[f] = ClusterColour(mesh.face_labels[f]);
  return colours;
}

std::string SceneJson(const ReportInputs& in) {
  Eigen::Vector3f min, max;
  geometry::Bounds(in.mesh, &min, &max);
  const Eigen::Vector3f centre = (min + max) / 2;
  const float radius = std::max((max - min).norm() / 2, 1e-3f);
  nlohmann::ordered_json json = {{"centre", {centre.x(), centre.y(), centre.z()}},
                                 {"radius", radius},
                                 {"mesh", MeshJson(in.mesh)}};
  json["points"] = in.points ? PointsJson(*in.points) : nlohmann::ordered_json();
  const std::map<std::string, std::string> phases = PhasesByImage(in);
  nlohmann::ordered_json cameras = nlohmann::ordered_json::array();
  for (const camera::NamedCamera& cam : in.cameras) {
    const auto phase = phases.find(std::filesystem::path(cam.name).filename().string());
    cameras.push_back(
        CameraJson(cam, centre.cast<double>(), phase == phases.end() ? "" : phase->second));
  }
  json["cameras"] = cameras;
  // "</" would end the <script> element early; "<\/" is the same JSON string.
  std::string text = json.dump();
  for (size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 3)) {
    text.replace(at, 2, "<\\/");
  }
  return text;
}

}  // namespace avc::report
