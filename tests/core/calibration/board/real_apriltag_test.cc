// Real-data check of tag poses on the ViSP eye-to-hand set (Franka Panda holding an AprilTag
// 36h11 id 10, 48 mm, seen by a fixed RealSense): every image yields the tag pose, and with the
// robot poses OpenCV's hand-eye solver (PARK) finds a tag-in-flange transform that stays constant
// to a few millimetres, as the data README reports.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "bench/calibration/hand_eye/hand_eye_comparison.h"
#include "bench/calibration/hand_eye/visp_hand_eye_set.h"
#include "core/calibration/board/board_pose.h"
#include "core/calibration/board/tag_detection.h"
#include "core/calibration/board/visp_camera.h"
#include "core/calibration/hand_eye/robot_world_hand_eye.h"
#include "tests/support/test_support.h"

namespace avc::calibration {
namespace {

cv::Mat Rotation(const Eigen::Isometry3d& T) {
  cv::Mat R(3, 3, CV_64F);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) R.at<double>(r, c) = T.linear()(r, c);
  return R;
}

cv::Mat Translation(const Eigen::Isometry3d& T) {
  return (cv::Mat_<double>(3, 1) << T.translation().x(), T.translation().y(), T.translation().z());
}

struct VispObservations {
  std::vector<Eigen::Isometry3d> T_flange_base, T_cam_tag;
};

// The 8 tag poses (asserting each detection is sound) and the inverted robot poses, read by the
// benchmark's reader of ViSP sets.
VispObservations LoadVispObservations(const std::filesystem::path& folder) {
  const bench::VispHandEyeSet set = bench::ReadVispHandEyeSet(folder, "franka", 10);
  EXPECT_EQ(set.intrinsics.width, 640);
  EXPECT_NEAR(set.intrinsics.fx, 607.593, 1e-3);
  EXPECT_DOUBLE_EQ(set.tag_size, 0.048);
  EXPECT_EQ(set.shots.size(), 8u);
  VispObservations observations;
  for (const bench::VispShot& shot : set.shots) {
    EXPECT_LT(shot.tag.rms_px, 0.5) << shot.image;
    EXPECT_GT(shot.tag.T_cam_tag.translation().z(), 0.1);
    EXPECT_LT(shot.tag.T_cam_tag.translation().z(), 2.0);
    // The tag faces the camera: its z axis points back towards it.
    EXPECT_LT(shot.tag.T_cam_tag.linear().col(2).z(), 0) << shot.image;
    observations.T_cam_tag.push_back(shot.tag.T_cam_tag);
    observations.T_flange_base.push_back(shot.T_base_flange.inverse());
  }
  return observations;
}

// How much the tag-in-flange translation T_flange_base,i * T_base_cam * T_cam_tag,i moves across
// the poses: {rms, largest} distance from its mean, metres. A right T_base_cam keeps it still.
std::pair<double, double> TagInFlangeSpread(const VispObservations& o,
                                            const Eigen::Isometry3d& T_base_cam) {
  std::vector<Eigen::Vector3d> tag_in_flange;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < o.T_cam_tag.size(); ++i) {
    tag_in_flange.push_back((o.T_flange_base[i] * T_base_cam * o.T_cam_tag[i]).translation());
    mean += tag_in_flange.back() / static_cast<double>(o.T_cam_tag.size());
  }
  double largest = 0, sum_squared = 0;
  for (const auto& t : tag_in_flange) {
    largest = std::max(largest, (t - mean).norm());
    sum_squared += (t - mean).squaredNorm();
  }
  return {std::sqrt(sum_squared / static_cast<double>(tag_in_flange.size())), largest};
}

std::filesystem::path VispFolder() {
  return avc::testing::SharedDataDir() / "handeye_visp" / "data-eye-to-hand";
}

TEST(RealAprilTag, TagPosesAgreeWithTheRobotThroughOpenCvHandEye) {
  if (!std::filesystem::exists(VispFolder() / "franka_camera.xml")) {
    GTEST_SKIP() << "shared data not found at " << VispFolder();
  }
  const VispObservations o = LoadVispObservations(VispFolder());
  // Eye-to-hand: T_flange_base,i * T_base_cam * T_cam_tag,i = T_flange_tag for every i, which is
  // calibrateHandEye's AX = XB with the inverted robot poses in the gripper-to-base slot.
  std::vector<cv::Mat> R_a, t_a, R_b, t_b;
  for (size_t i = 0; i < o.T_cam_tag.size(); ++i) {
    R_a.push_back(Rotation(o.T_flange_base[i]));
    t_a.push_back(Translation(o.T_flange_base[i]));
    R_b.push_back(Rotation(o.T_cam_tag[i]));
    t_b.push_back(Translation(o.T_cam_tag[i]));
  }
  cv::Mat R_base_cam, t_base_cam;
  cv::calibrateHandEye(R_a, t_a, R_b, t_b, R_base_cam, t_base_cam, cv::CALIB_HAND_EYE_PARK);
  cv::Mat rvec;
  cv::Rodrigues(R_base_cam, rvec);
  const auto [rms, largest] = TagInFlangeSpread(o, PoseFromRvecTvec(rvec, t_base_cam));
  std::cout << "OpenCV PARK: tag in flange deviation rms " << rms * 1e3 << " mm, largest "
            << largest * 1e3 << " mm\n";
  // README: constant to 1.5-3 mm. Measured 2.3 mm rms, 4.1 mm largest.
  EXPECT_LT(rms, 0.003);
  EXPECT_LT(largest, 0.005);
}

TEST(RealAprilTag, OurClosedFormKeepsTheTagInFlangeConstantToAboutThreeMillimetres) {
  if (!std::filesystem::exists(VispFolder() / "franka_camera.xml")) {
    GTEST_SKIP() << "shared data not found at " << VispFolder();
  }
  const VispObservations o = LoadVispObservations(VispFolder());
  // Eye-to-hand in our A X = Z B: A = T_cam_tag, B = T_base_flange (the solver inverts what it is
  // given, so it gets T_flange_base), X = T_tag_flange, Z = T_cam_base.
  std::vector<hand_eye::HandEyeObservation> observations;
  for (size_t i = 0; i < o.T_cam_tag.size(); ++i) {
    observations.push_back({o.T_flange_base[i], o.T_cam_tag[i]});
  }
  const hand_eye::HandEyeSolution solution = hand_eye::SolveRobotWorldHandEye(observations);
  const auto [rms, largest] = TagInFlangeSpread(o, solution.T_cam_flange.inverse());
  std::cout << "D&H closed form: tag in flange deviation rms " << rms * 1e3 << " mm, largest "
            << largest * 1e3 << " mm\n";
  // Measured 2.09 mm rms, 3.13 mm largest (OpenCV PARK: 2.28 / 4.09 on the same poses).
  EXPECT_LT(rms, 0.0025);
  EXPECT_LT(largest, 0.0035);
}

// Issue 39's acceptance on real data: the hand-eye `avc calibrate solve` writes predicts a
// left-out pose at least as well as every OpenCV method and our closed form, in rotation and in
// translation (the comparison `avc bench calibration` reports).
TEST(RealAprilTag, TheWrittenHandEyePredictsLeftOutPosesBestOfAllMethods) {
  if (!std::filesystem::exists(VispFolder() / "franka_camera.xml")) {
    GTEST_SKIP() << "shared data not found at " << VispFolder();
  }
  const nlohmann::json result = bench::RunRealEyeToHand(VispFolder());
  const nlohmann::json* written = nullptr;
  for (const nlohmann::json& m : result["methods"]) {
    if (m.value("written", false)) written = &m;
  }
  ASSERT_NE(written, nullptr);
  const double rotation = (*written)["loo_rotation_deg"],
               translation = (*written)["loo_translation_mm"];
  std::cout << "written: " << (*written)["method"] << ", leave-one-out " << rotation << " deg, "
            << translation << " mm\n";
  // Measured 0.699 deg / 1.99 mm (OpenCV Park 1.015 / 2.31, our closed form 1.054 / 2.33).
  EXPECT_LT(rotation, 0.8);
  EXPECT_LT(translation, 2.2);
  int compared = 0;
  for (const nlohmann::json& m : result["methods"]) {
    if (m["source"] == "ours" && m["method"] != "closed form") continue;
    EXPECT_LE(rotation, m["loo_rotation_deg"].get<double>()) << m["method"];
    EXPECT_LE(translation, m["loo_translation_mm"].get<double>()) << m["method"];
    ++compared;
  }
  EXPECT_EQ(compared, 8);  // 7 OpenCV methods and the closed form
}

TEST(RealAprilTag, NamesMissingTagsAndBadCameraFiles) {
  const cv::Mat blank(480, 640, CV_8U, cv::Scalar(200));
  camera::Intrinsics intrinsics;
  intrinsics.width = 640;
  intrinsics.height = 480;
  intrinsics.fx = intrinsics.fy = 600;
  intrinsics.cx = 320;
  intrinsics.cy = 240;
  try {
    DetectTagPose(blank, 10, 0.048, intrinsics, "blank.png");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("id 10"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("blank.png"), std::string::npos) << e.what();
  }
  EXPECT_THROW(DetectTagPose(blank, 10, -1, intrinsics, "x"), std::invalid_argument);
  avc::testing::TempDir dir;
  avc::testing::WriteFile(dir / "cam.xml", "<root><px>600</px><py>abc</py></root>");
  try {
    ReadVispCameraXml(dir / "cam.xml");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cam.xml"), std::string::npos) << e.what();
  }
  avc::testing::WriteFile(dir / "cam2.xml",
                          "<image_width>640</image_width><image_height>480</image_height>"
                          "<px>600</px><py>abc</py><u0>320</u0><v0>240</v0>");
  try {
    ReadVispCameraXml(dir / "cam2.xml");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("<py>"), std::string::npos) << e.what();
  }
  EXPECT_THROW(ReadVispCameraXml(dir / "absent.xml"), std::runtime_error);
}

}  // namespace
}  // namespace avc::calibration
