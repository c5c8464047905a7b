#include "tests/report/report_test_scan.h"

#include <Eigen/Geometry>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/camera/camera_io.h"
#include "core/geometry/mesh_io.h"
#include "core/geometry/point_cloud_io.h"
#include "orchestrator/scan_record.h"
#include "tests/support/test_support.h"

namespace avc::testing {
namespace {

namespace fs = std::filesystem;

}  // namespace

camera::NamedCamera LookingAtOrigin(const std::string& name, const Eigen::Vector3d& eye) {
  const Eigen::Vector3d forward = -eye.normalized();
  const Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d down = forward.cross(right);
  Eigen::Matrix3d R_world_cam;
  R_world_cam << right, down, forward;
  Eigen::Isometry3d T_world_cam = Eigen::Isometry3d::Identity();
  T_world_cam.linear() = R_world_cam;
  T_world_cam.translation() = eye;
  camera::NamedCamera cam{name, {}};
  cam.camera.intrinsics = {640, 480, 600, 600, 320, 240, {}};
  cam.camera.T_cam_world = T_world_cam.inverse();
  return cam;
}

geometry::Mesh Tetrahedron() {
  geometry::Mesh mesh;
  mesh.vertices = {{0, 0, 0}, {0.1f, 0.02f, 0.01f}, {0.03f, 0.09f, 0.02f}, {0.04f, 0.03f, 0.1f}};
  mesh.faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  mesh.face_labels = {0, 0, 1, 1};
  mesh.colors = {{30, 120, 40}, {40, 150, 50}, {50, 170, 60}, {60, 190, 70}};
  return mesh;
}

geometry::Mesh WavySheet(int n) {
  geometry::Mesh mesh;
  const float size = 0.1f;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const float x = size * i / n - size / 2, y = size * j / n - size / 2;
      mesh.vertices.emplace_back(x, y, 0.05f + 0.3f * x * x + 0.01f * std::sin(60 * y) + 0.2f * y);
      mesh.colors.push_back(
          {static_cast<uint8_t>(40 + 150 * i / n), 160, static_cast<uint8_t>(40 + 150 * j / n)});
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      const int cluster = (i * 2 / n) + 2 * (j * 2 / n);
      mesh.faces.emplace_back(a, b, d);
      mesh.faces.emplace_back(a, d, c);
      mesh.face_labels.insert(mesh.face_labels.end(), {cluster, cluster});
    }
  }
  return mesh;
}

void WriteTestScan(const fs::path& dir, const geometry::Mesh& mesh) {
  fs::create_directories(dir / "model");
  geometry::WriteMeshPly(dir / "model" / "mesh.ply", mesh);
  geometry::PointCloud points;
  for (const Eigen::Vector3f& v : mesh.vertices) points.positions.push_back(v);
  points.colors.assign(points.size(), {200, 40, 40});
  geometry::WritePointCloudPly(dir / "model" / "points.ply", points);
  camera::WriteCamerasJson(dir / "cameras.json",
                           {LookingAtOrigin("view_0000.png", {0.4, -0.1, 0.25}),
                            LookingAtOrigin("view_0002.png", {-0.2, 0.35, 0.3})});

  orchestrator::ScanRecord record;
  record.scan_id = kTestScanId;
  record.cell = "cell0";
  record.created_utime = 1700000000000000;  // 2023-11-14 22:13:20 UTC
  record.state = orchestrator::ScanState::kDone;
  record.phases = {{"FRAME", 1700000000000000, 1700000012000000},
                   {"BUILD", 1700000012000000, 1700000042500000}};
  const char* phases[] = {"frame", "initial", "active"};
  for (int i = 0; i < 3; ++i) {
    orchestrator::CaptureRecord c;
    c.index = i;
    c.image_id = "view_000" + std::to_string(i);
    c.file = "images/" + c.image_id + ".png";
    c.sha256 = std::string(64, 'a' + i);
    c.phase = phases[i];
    c.reason = std::string("reason of view ") + std::to_string(i);
    c.kept = i != 1;
    c.table_angle = i * 0.5;
    record.captures.push_back(c);
  }
  orchestrator::SaveScanRecord(record, dir);

  const nlohmann::json report = {
      {"scan_id", kTestScanId},
      {"phases",
       {{{"state", "FRAME"}, {"seconds", 12.0}}, {{"state", "BUILD"}, {"seconds", 30.5}}}},
      {"images", {{"captured", 3}, {"kept", 2}}},
      {"planner",
       {{"planner_notes", {"patch 3 seen by 1 view"}}, {"patches", 7}, {"failing_patches", 1}}},
      {"stages",
       {{"build",
         {{"service", "avc-builder"},
          {"config_sha256", "0123456789abcdef0123456789abcdef"},
          {"config_file", "config/avc-builder.toml"}}},
        {"surface", {{"service", "avc-surfacer"}}}}},
      {"build",
       {{"points", 1234},
        {"merged", {{"points", 567}}},
        {"soil", {{"z_m", 0.118}, {"contrast", 0.3}, {"patches", 1800}}},
        {"ground_truth",
         {{"accuracy",
           {{"mean_m", 0.0012}, {"rmse_m", 0.0015}, {"median_m", 0.001}, {"p90_m", 0.002}}},
          {"scores",
           {{{"threshold_m", 0.002},
             {"precision", 0.91},
             {"recall", 0.87},
             {"fscore", 0.889}}}}}}}},
      {"surface",
       {{"clusters", 9},
        {"points_used", 2900},
        {"points_left_out", 4},
        {"cells", 12},
        {"stitch_faces", 77},
        {"area_m2_after_phase", {{"1", 0.0061}, {"2", 0.0079}, {"3", 0.0078}, {"4", 0.00789}}},
        {"components", 2},
        {"warnings", {"cluster 7 (2 points): fewer than 3 points; its points are left out"}}}},
      {"traits",
       {{"height_m", 0.123},
        {"width_m", 0.0987},
        {"hull_volume_m3", 0.000456},
        {"total_area_m2", 0.00789},
        {"faces", mesh.num_faces()},
        {"mean_curvature_per_m", 12.5},
        {"clusters",
         {{{"cluster", 0}, {"area_m2", 0.004}, {"inclination_deg", 35.5}, {"azimuth_deg", 120.25}},
          {{"cluster", 1},
           {"area_m2", 0.00389},
           {"inclination_deg", 60},
           {"azimuth_deg", -45}}}}}}};
  WriteFile(dir / "report.json", report.dump(2));
}

}  // namespace avc::testing
