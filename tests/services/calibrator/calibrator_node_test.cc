// avc-calibrator's node on an in-process bus: it publishes its calibration, gives every captured
// image the camera of the arm and table state at the request (and none while they move), and
// answers camera queries by joints or flange pose exactly as the calibration computes them.

#include "services/calibrator/calibrator_node.h"

#include <gtest/gtest.h>

#include <avc/ack_t.hpp>
#include <avc/calibration_t.hpp>
#include <avc/camera_t.hpp>
#include <map>

#include "core/bus/channels.h"
#include "core/calibration/cell/calibration_yaml.h"
#include "core/kinematics/forward_kinematics.h"

namespace avc::calibrator {
namespace {

using std::chrono::milliseconds;

calibration::CellCalibration TestCalibration() {
  calibration::CellCalibration calibration;
  calibration.intrinsics.width = 1280;
  calibration.intrinsics.height = 960;
  calibration.intrinsics.fx = calibration.intrinsics.fy = 1500;
  calibration.intrinsics.cx = 639.5;
  calibration.intrinsics.cy = 479.5;
  calibration.T_flange_cam.translation() << 0.06, 0.08, 0.02;
  calibration.T_base_table.translation() << 0.55, 0.01, -0.2;
  calibration.T_base_table.linear() =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.01, 0.02, 1).normalized()).toRotationMatrix();
  return calibration;
}

kinematics::JointVector Joints() {
  return (kinematics::JointVector() << 0.2, -1.3, 1.4, -1.7, -1.5, 0.3).finished();
}

struct Harness {
  Harness()
      : bus(bus::InProcessBusOptions()),
        heartbeat(bus, loop, "avc-calibrator", milliseconds(50)),
        calibration(TestCalibration()) {
    bus.AttachTo(loop);
    bus.Subscribe<avc::camera_t>(channels::kCamera,
                                 [this](const avc::camera_t& camera, const bus::RxInfo&) {
                                   cameras[camera.image_id] = camera;
                                 });
    bus.Subscribe<avc::ack_t>(channels::kAck, [this](const avc::ack_t& ack, const bus::RxInfo&) {
      acks[ack.request_id] = ack;
    });
    bus.Subscribe<avc::calibration_t>(
        channels::kCalibration,
        [this](const avc::calibration_t& message, const bus::RxInfo&) { published = message; });
    CalibratorNodeOptions options;
    options.source = "test.yaml";
    options.republish_period = milliseconds(100);
    node = std::make_unique<CalibratorNode>(bus, loop, heartbeat, calibration, options);
  }

  void States(const Eigen::Isometry3d& T_base_flange, double angle, bool moving) {
    avc::robot_state_t robot{};
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) robot.T_base_flange[4 * r + c] = T_base_flange.matrix()(r, c);
    }
    robot.moving = moving;
    avc::turntable_state_t table{};
    table.angle = angle;
    table.connected = true;
    bus.Publish(channels::kRobotState, robot);
    bus.Publish(channels::kTurntableState, table);
    loop.RunUntil([] { return false; }, milliseconds(20));
  }

  void Capture(const std::string& image_id) {
    avc::capture_request_t request{};
    request.request_id = "r-" + image_id;
    request.image_id = image_id;
    bus.Publish(channels::kCaptureRequest, request);
    loop.RunUntil([] { return false; }, milliseconds(20));
  }

  static Eigen::Matrix4d Pose(const avc::camera_t& camera) {
    Eigen::Matrix4d m;
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) m(r, c) = camera.T_cam_world[4 * r + c];
    }
    return m;
  }

  bus::Bus bus;
  bus::EventLoop loop;
  bus::HeartbeatPublisher heartbeat;
  calibration::CellCalibration calibration;
  std::unique_ptr<CalibratorNode> node;
  std::map<std::string, avc::camera_t> cameras;
  std::map<std::string, avc::ack_t> acks;
  std::optional<avc::calibration_t> published;
};

TEST(CalibratorNode, PublishesTheCalibrationItServes) {
  Harness h;
  ASSERT_TRUE(h.loop.RunUntil([&] { return h.published.has_value(); }, milliseconds(1000)));
  EXPECT_EQ(h.published->source, "test.yaml");
  EXPECT_EQ(h.published->format_version, 1);
  EXPECT_EQ(h.published->yaml, calibration::CalibrationToYaml(h.calibration));
  EXPECT_EQ(calibration::CalibrationFromYaml(h.published->yaml, "bus").T_base_table.matrix(),
            h.calibration.T_base_table.matrix());
}

TEST(CalibratorNode, EveryCaptureGetsTheCameraOfTheStillArmAndTable) {
  Harness h;
  const Eigen::Isometry3d flange = kinematics::ForwardKinematics(h.calibration.dh, Joints());
  h.Capture("too_early");  // no state yet: no camera, rather than a guess
  h.States(flange, 1.1, /*moving=*/true);
  h.Capture("while_moving");
  h.States(flange, 1.1, /*moving=*/false);
  h.Capture("view_0001");
  ASSERT_TRUE(
      h.loop.RunUntil([&] { return h.cameras.count("view_0001") != 0; }, milliseconds(1000)));
  EXPECT_EQ(h.cameras.count("too_early"), 0u);
  EXPECT_EQ(h.cameras.count("while_moving"), 0u);
  const avc::camera_t& camera = h.cameras.at("view_0001");
  EXPECT_EQ(camera.camera_id, "cam0");
  EXPECT_EQ(camera.width, 1280);
  EXPECT_EQ(camera.fx, 1500);
  EXPECT_LT((Harness::Pose(camera) - h.calibration.CameraAt(flange, 1.1).T_cam_world.matrix())
                .cwiseAbs()
                .maxCoeff(),
            1e-12);
  EXPECT_EQ(h.node->cameras_published(), 1);
}

TEST(CalibratorNode, AnswersQueriesByJointsOrFlangeAndRefusesBadOnes) {
  Harness h;
  avc::camera_query_t by_joints{};
  by_joints.request_id = "q1";
  by_joints.kind = avc::camera_query_t::KIND_JOINTS;
  for (int i = 0; i < 6; ++i) by_joints.q[i] = Joints()[i];
  by_joints.table_angle = -0.4;
  h.bus.Publish(channels::kCameraQuery, by_joints);
  avc::camera_query_t by_flange{};
  by_flange.request_id = "q2";
  by_flange.kind = avc::camera_query_t::KIND_FLANGE;
  const Eigen::Isometry3d flange = kinematics::ForwardKinematics(h.calibration.dh, Joints());
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) by_flange.T_base_flange[4 * r + c] = flange.matrix()(r, c);
  }
  by_flange.table_angle = -0.4;
  h.bus.Publish(channels::kCameraQuery, by_flange);
  avc::camera_query_t bad = by_joints;
  bad.request_id = "q3";
  bad.q[5] = std::nan("");
  h.bus.Publish(channels::kCameraQuery, bad);
  ASSERT_TRUE(h.loop.RunUntil([&] { return h.acks.size() == 3; }, milliseconds(1000)));

  const Eigen::Matrix4d expected =
      h.calibration.CameraAtJoints(Joints(), -0.4).T_cam_world.matrix();
  EXPECT_LT((Harness::Pose(h.cameras.at("q1")) - expected).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((Harness::Pose(h.cameras.at("q2")) - expected).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(h.acks.at("q1").status, avc::ack_t::STATUS_DONE);
  EXPECT_EQ(h.acks.at("q3").status, avc::ack_t::STATUS_REFUSED);
  EXPECT_NE(h.acks.at("q3").reason.find("joint 6"), std::string::npos) << h.acks.at("q3").reason;
  EXPECT_EQ(h.cameras.count("q3"), 0u);
}

}  // namespace
}  // namespace avc::calibrator
