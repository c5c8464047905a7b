// Writes the seed corpus, fuzz/corpus/<target>/*, with the project's own writers and encoders so
// every seed is an input the project itself produces: make_seeds <corpus dir> <source dir>.
// Seeds are small (a few points, two triangles); the fuzzers grow them.

#include <octomap/OcTree.h>

#include <algorithm>
#include <avc/robot_command_t.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <lcm/lcm-cpp.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "core/auth/command_auth.h"
#include "core/calibration/cell/calibration_yaml.h"
#include "core/camera/camera_io.h"
#include "core/geometry/mesh_io.h"
#include "core/geometry/point_cloud_io.h"
#include "core/kinematics/row_major_pose.h"
#include "core/messages/camera_message.h"
#include "core/messages/clusters_message.h"
#include "core/messages/mesh_message.h"
#include "core/messages/mvs_points_message.h"
#include "core/messages/point_records.h"
#include "core/plan/plan_exchange.h"
#include "core/products/chunking.h"
#include "core/util/clock.h"
#include "core/util/file_io.h"
#include "core/util/sha256.h"
#include "orchestrator/scan_record.h"

#include "fuzz/fuzz_support.h"
#include "fuzz/lcm_types.inc"

namespace avc::fuzz {
namespace {
namespace fs = std::filesystem;

fs::path corpus;

void Seed(const std::string& target, const std::string& name, std::string_view bytes) {
  fs::create_directories(corpus / target);
  WriteFile(corpus / target, name, bytes);
}

template <class T>
std::string Encode(const T& message) {
  std::string bytes(static_cast<size_t>(message.getEncodedSize()), '\0');
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

camera::Camera TestCamera() {
  camera::Camera camera;
  camera.intrinsics = {4, 3, 5.0, 5.0, 1.5, 1.0, {0.01, -0.002, 0, 0, 0}};
  camera.T_cam_world.translation() << 0.01, -0.02, 0.5;
  camera.T_cam_world.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()).matrix();
  return camera;
}

// Two triangles over four coloured, textured, labelled vertices.
geometry::Mesh TestMesh() {
  geometry::Mesh mesh;
  mesh.vertices = {{0, 0, 0}, {0.01f, 0, 0}, {0, 0.01f, 0}, {0.01f, 0.01f, 0.002f}};
  mesh.faces = {{0, 1, 2}, {1, 3, 2}};
  mesh.uvs = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
  mesh.colors = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {9, 9, 9}};
  mesh.face_labels = {1, 2};
  mesh.face_materials = {0, 0};
  return mesh;
}

geometry::PointCloud TestCloud() {
  geometry::PointCloud cloud;
  cloud.positions = {{0, 0, 0}, {0.01f, 0, 0.002f}, {0, 0.01f, 0.004f}};
  cloud.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0.6f, 0.8f}};
  cloud.colors = {{10, 20, 30}, {40, 50, 60}, {70, 80, 90}};
  return cloud;
}

std::string OctreeBytes(bool pruned) {
  octomap::OcTree tree(0.002);
  tree.updateNode(octomap::point3d(0.01f, 0.01f, 0.01f), true);
  tree.updateNode(octomap::point3d(0.02f, 0.01f, 0.01f), false);
  if (pruned) {
    for (float x : {0.0005f, 0.0025f}) {
      for (float y : {0.0005f, 0.0025f}) {
        for (float z : {0.0005f, 0.0025f}) tree.updateNode(octomap::point3d(x, y, z), true);
      }
    }
    tree.prune();
  }
  std::ostringstream bytes;
  tree.writeBinaryConst(bytes);
  return bytes.str();
}

// An RGB8 raw image_t of one grey level.
avc::image_t RawImage(int width, int height, uint8_t grey) {
  avc::image_t image{};
  image.image_id = "view_0000";
  image.width = width;
  image.height = height;
  image.pixel_format = avc::image_t::PIXEL_RGB8;
  image.encoding = avc::image_t::ENCODING_RAW;
  image.data.assign(static_cast<size_t>(width) * height * 3, grey);
  image.size = static_cast<int32_t>(image.data.size());
  return image;
}

std::string ReadBack(const fs::path& path) { return ReadFile(path); }

void MeshSeeds() {
  const fs::path dir = FreshDir("mesh");
  geometry::Mesh plain = TestMesh();
  plain.uvs.clear();
  plain.colors.clear();
  plain.face_labels.clear();
  plain.face_materials.clear();
  geometry::WriteMeshPly(dir / "a.ply", TestMesh(), /*binary=*/true);
  Seed("ply", "mesh_binary.ply", ReadBack(dir / "a.ply"));
  geometry::WriteMeshPly(dir / "a.ply", TestMesh(), /*binary=*/false);
  Seed("ply", "mesh_ascii.ply", ReadBack(dir / "a.ply"));
  geometry::WritePointCloudPly(dir / "a.ply", TestCloud(), /*binary=*/true);
  Seed("ply", "cloud_binary.ply", ReadBack(dir / "a.ply"));
  geometry::WritePointCloudPly(dir / "a.ply", TestCloud(), /*binary=*/false);
  Seed("ply", "cloud_ascii.ply", ReadBack(dir / "a.ply"));
  geometry::WriteMeshObj(dir / "a.obj", TestMesh());
  Seed("obj", "mesh.obj", ReadBack(dir / "a.obj"));
  geometry::WriteMeshObj(dir / "a.obj", plain);
  Seed("obj", "plain.obj", ReadBack(dir / "a.obj"));
  geometry::WriteMeshOff(dir / "a.off", TestMesh());
  Seed("off", "coloured.off", ReadBack(dir / "a.off"));
  geometry::WriteMeshOff(dir / "a.off", plain);
  Seed("off", "plain.off", ReadBack(dir / "a.off"));
}

void MessageSeeds() {
  // Every type, zeroed: a valid encoding for each fingerprint.
#define AVC_FUZZ_LCM_TYPE(type) Seed("lcm_messages", #type "_empty", Encode(avc::type{}));
  AVC_FUZZ_ALL_LCM_TYPES
#undef AVC_FUZZ_LCM_TYPE
  Seed("lcm_messages", "camera_t", Encode(messages::CameraToMessage(TestCamera(), "a.png", "cam")));

  mvs::MvsPoints points;
  points.cloud = TestCloud();
  points.confidence = {0.9f, 0.8f, 0.7f};
  points.views = {{0, 1}, {1}, {0}};
  Seed("lcm_messages", "mvs_points_t",
       Encode(messages::MvsPointsToMessage(points, {"view_0000", "view_0001"}, "scan-mvs-1")));

  messages::ClustersContent clusters;
  clusters.cloud_id = "scan-mvs-1";
  clusters.map_id = "scan-ppr-0001";
  clusters.num_clusters = 2;
  clusters.raw_points = 30;
  clusters.merged.voxel_size = 0.002;
  clusters.merged.cloud = TestCloud();
  clusters.merged.confidence = {0.9f, 0.8f, 0.7f};
  clusters.merged.point_counts = {10, 12, 8};
  clusters.merged.voxels = {{0, 0, 0}, {5, 0, 1}, {0, 5, 2}};
  clusters.clusters = {0, 1, -1};
  Seed("lcm_messages", "clusters_t", Encode(messages::ClustersToMessage(clusters)));

  Seed("lcm_messages", "mesh_t", Encode(messages::MeshToMessage(TestMesh(), "scan-mesh")));

  avc::point_cloud_t cloud = messages::MakePointCloud(
      "cloud", {{"x"}, {"y"}, {"z"}, {"red", avc::point_field_t::TYPE_UINT8}}, 2);
  Seed("lcm_messages", "point_cloud_t", Encode(cloud));

  avc::voxel_map_t map{};
  map.map_id = "scan-ppr-0001";
  map.frame = "world";
  map.resolution = 0.002;
  map.encoding = avc::voxel_map_t::ENCODING_OCTOMAP_BT;
  const std::string tree = OctreeBytes(/*pruned=*/true);
  map.data.assign(tree.begin(), tree.end());
  map.data_size = static_cast<int32_t>(map.data.size());
  Seed("lcm_messages", "voxel_map_t", Encode(map));

  Seed("lcm_messages", "image_t_raw", Encode(RawImage(4, 3, 128)));

  Seed("voxel_map", "one_voxel.bt", OctreeBytes(/*pruned=*/false));
  Seed("voxel_map", "pruned.bt", tree);
}

void ChunkSeeds() {
  // A raw 32x24 image: three chunks of the smallest payload the chunker allows (1025 bytes).
  const avc::image_t image = RawImage(32, 24, 77);
  products::Product product;
  product.product_id = "p-1";
  product.name = "images/view_0000";
  product.content_type = products::ContentTypeOf<avc::image_t>();
  product.source = "avc-camera";
  const std::string bytes = Encode(image);
  product.payload.assign(bytes.begin(), bytes.end());
  product.sha256 = Sha256Hex(bytes);
  const size_t overhead = 1 << 20;
  const size_t cap = overhead - products::ChunkPayloadBytes(overhead, product) + 1025;
  std::vector<std::string> chunks;
  for (const avc::product_chunk_t& chunk : products::SplitIntoChunks(product, cap)) {
    chunks.push_back(Encode(chunk));
  }
  const auto stream = [&](const std::vector<size_t>& order) {
    std::string out;
    for (size_t i : order) {
      out.push_back(static_cast<char>(chunks[i].size() & 0xff));
      out.push_back(static_cast<char>(chunks[i].size() >> 8));
      out += chunks[i];
    }
    return out;
  };
  std::vector<size_t> in_order;
  for (size_t i = 0; i < chunks.size(); ++i) in_order.push_back(i);
  Seed("product_chunks", "in_order", stream(in_order));
  std::vector<size_t> shuffled(in_order.rbegin(), in_order.rend());
  shuffled.push_back(0);  // a retransmission after completion
  Seed("product_chunks", "reversed_repeat", stream(shuffled));
}

void FileSeeds(const fs::path& source) {
  calibration::CellCalibration calibration;
  calibration.intrinsics = {1280, 960, 1500, 1500, 639.5, 479.5, {0.01, -0.02, 0, 0, 0.001}};
  calibration.T_flange_cam.translation() << 0.06, 0.08, 0.02;
  calibration.T_base_table.translation() << 0.55, 0.01, -0.2;
  calibration.T_base_table.linear() =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.01, 0.02, 1).normalized()).toRotationMatrix();
  calibration.residuals.view_names = {"view_0000"};
  calibration.residuals.view_rms_px = {0.3};
  calibration.residuals.rejected = {"view_0001: board not found"};
  calibration.note = "seed";
  Seed("calibration_yaml", "calibration.yaml", calibration::CalibrationToYaml(calibration));

  const fs::path dir = FreshDir("dataset");
  const std::vector<camera::NamedCamera> cameras = {{"a.png", TestCamera()}};
  camera::WriteCamerasJson(dir / "cameras.json", cameras);
  Seed("dataset", "scan", "0" + ReadFile(dir / "cameras.json"));
  camera::WriteColmapText(dir, cameras);
  Seed("dataset", "colmap",
       "1" + ReadFile(dir / "cameras.txt") + std::string(kPartSeparator) +
           ReadFile(dir / "images.txt"));
  Seed("dataset", "middlebury",
       "2" + std::string("1\na.png 5 0 1.5 0 5 1 0 0 1 1 0 0 0 1 0 0 0 1 0.01 -0.02 0.5\n"));

  orchestrator::ScanRecord record;
  record.scan_id = "scan-1";
  record.cell = "cell";
  record.created_utime = 1700000000000000;
  record.state = orchestrator::ScanState::kActiveVision;
  record.StartPhase(orchestrator::ScanState::kFrame, 1700000000000000);
  record.StartPhase(orchestrator::ScanState::kActiveVision, 1700000001000000);
  orchestrator::CaptureRecord capture;
  capture.image_id = "view_0000";
  capture.file = "images/view_0000.png";
  capture.sha256 = std::string(64, 'a');
  capture.joints = {0.2, -1.3, 1.4, -1.7, -1.5, 0.3};
  capture.reported_T_base_flange = {1, 0, 0, 0.4, 0, 1, 0, 0.1, 0, 0, 1, 0.3, 0, 0, 0, 1};
  capture.phase = "frame";
  capture.reason = "framing";
  record.captures.push_back(capture);
  record.options = {{"initial_views", 30}};
  orchestrator::SaveScanRecord(record, dir);
  Seed("scan_record", "scan.json", ReadFile(dir / "scan.json"));

  // A plan job with one answered view and one refused, and an answer asking for a third.
  plan::PlanRequest request;
  const cv::Mat mask = cv::Mat::zeros(6, 8, CV_8UC1);
  mask(cv::Rect(2, 2, 3, 2)).setTo(255);
  request.answered.push_back(
      {{kinematics::JointVector::Constant(0.25), 0.5}, plan::EncodeMask(mask)});
  request.answered.push_back({{kinematics::JointVector::Constant(-0.5), 1.0}, std::nullopt});
  plan::PlanAnswer answer;
  answer.phase = plan::PlanPhase::kInitialCapture;
  answer.next = plan::ViewRequest{kinematics::JointVector::Constant(0.1), -0.2};
  answer.keep_out.z0_m = -0.01;
  answer.keep_out.radius_m = {0.1, 0.12};
  answer.settings = {{"max_views", "14"}};
  const fs::path plan_dir = dir / "plan";
  plan::WritePlanRequest(request, plan_dir);
  plan::WritePlanAnswer(answer, plan_dir);
  Seed("plan_exchange", "two_views",
       ReadFile(plan_dir / plan::kRequestFile) + std::string(kPartSeparator) +
           ReadFile(plan_dir / plan::kAnswerFile) + std::string(kPartSeparator) +
           ReadFile(plan_dir / "masks/view_0000.png"));

  for (const auto& entry : fs::directory_iterator(source / "launch")) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".toml" && ext != ".yaml") continue;
    Seed("launch_file", entry.path().filename().string(),
         (ext == ".toml" ? "0" : "1") + ReadFile(entry.path()));
  }

  // A log of a few events, and the same cut inside its last event.
  const fs::path log = dir / "seed.lcmlog";
  {
    lcm::LogFile file(log.string(), "w");
    const std::vector<std::pair<std::string, std::string>> events = {
        {"cell/HEARTBEAT", Encode(avc::heartbeat_t{})},
        {"cell/CAMERA", Encode(messages::CameraToMessage(TestCamera(), "a.png", "cam"))},
        {"cell/RUN_INFO", Encode(avc::run_info_t{})}};
    int64_t utime = 1700000000000000;
    for (const auto& [channel, bytes] : events) {
      lcm::LogEvent event{};
      event.timestamp = utime += 1000;
      event.channel = channel;
      event.datalen = static_cast<int32_t>(bytes.size());
      event.data = const_cast<char*>(bytes.data());
      file.writeEvent(&event);
    }
  }
  const std::string log_bytes = ReadFile(log);
  Seed("lcm_log", "three_events.lcmlog", log_bytes);
  Seed("lcm_log", "truncated.lcmlog", log_bytes.substr(0, log_bytes.size() - 7));
}

// Signed as the robot_command target's verifier expects (key 0x5a.., cell0, a fixed clock so the
// corpus is the same every time): a joint move, a tool move, a plant keep-out, an unsigned stop.
void RobotCommandSeeds() {
  const ManualClock clock(1'700'000'000'000'000);
  auth::CommandKey key;
  key.bytes.fill(0x5a);
  auth::CommandSigner signer(key, "seed", "cell0", &clock);
  avc::robot_command_t move{};
  move.request_id = "move-1";
  move.kind = avc::robot_command_t::KIND_MOVE_JOINTS;
  const double q[6] = {0.6, -1.3, 1.5, -1.8, -1.5, 0.2};
  std::copy(std::begin(q), std::end(q), move.q);
  move.speed = 0.5;
  move.acceleration = 0.8;
  signer.Sign(move, "cell0/ROBOT_COMMAND");
  Seed("robot_command", "move_joints", Encode(move));

  // A tool move: its pose a finite rigid transform, so the fuzzer starts inside the linear-move
  // path (inverse kinematics along the line) instead of having to find a rotation.
  avc::robot_command_t line{};
  line.request_id = "move-2";
  line.kind = avc::robot_command_t::KIND_MOVE_LINEAR;
  Eigen::Isometry3d target = Eigen::Isometry3d::Identity();
  target.linear() = Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()).toRotationMatrix();
  target.translation() = Eigen::Vector3d(0.4, 0.1, 0.3);
  kinematics::RowMajorFromIsometry(target, line.T_base_flange);
  line.speed = 0.1;
  line.acceleration = 0.5;
  signer.Sign(line, "cell0/ROBOT_COMMAND");
  Seed("robot_command", "move_linear", Encode(line));

  avc::robot_command_t keep_out{};
  keep_out.request_id = "keep-out-1";
  keep_out.kind = avc::robot_command_t::KIND_SET_PLANT_KEEP_OUT;
  kinematics::RowMajorFromIsometry(Eigen::Isometry3d(Eigen::Translation3d(0.55, 0, -0.2)),
                                   keep_out.T_base_table);
  keep_out.keep_out_z0 = -0.02;
  keep_out.keep_out_slab = 0.02;
  keep_out.keep_out_radius = {0.05, 0.12, 0.2, 0.18, 0.1};
  keep_out.keep_out_slabs = static_cast<int16_t>(keep_out.keep_out_radius.size());
  signer.Sign(keep_out, "cell0/ROBOT_COMMAND");
  Seed("robot_command", "plant_keep_out", Encode(keep_out));

  avc::robot_command_t stop{};
  stop.request_id = "stop-1";
  stop.kind = avc::robot_command_t::KIND_STOP;
  Seed("robot_command", "unsigned_stop", Encode(stop));
}

}  // namespace
}  // namespace avc::fuzz

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s CORPUS_DIR SOURCE_DIR\n", argv[0]);
    return 2;
  }
  avc::fuzz::corpus = argv[1];
  avc::fuzz::MeshSeeds();
  avc::fuzz::MessageSeeds();
  avc::fuzz::ChunkSeeds();
  avc::fuzz::FileSeeds(argv[2]);
  avc::fuzz::RobotCommandSeeds();
  return 0;
}
