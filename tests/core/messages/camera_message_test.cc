// Cameras on the bus: camera_t -> Camera -> camera_t keeps every value, and cameras that are not
// usable (non-finite or bad intrinsics, a pose that is not a rigid transform) are refused by field.

#include "core/messages/camera_message.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace avc::messages {
namespace {

avc::camera_t GoodCamera() {
  avc::camera_t camera{};
  camera.image_id = "view_3";
  camera.width = 320;
  camera.height = 240;
  camera.fx = camera.fy = 400;
  camera.cx = 159.5;
  camera.cy = 119.5;
  camera.distortion[0] = -0.1;
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) camera.T_cam_world[4 * r + c] = rotation(r, c);
    camera.T_cam_world[4 * r + 3] = std::array{0.1, 0.2, 0.3}[static_cast<size_t>(r)];
  }
  camera.T_cam_world[15] = 1;
  return camera;
}

std::string ErrorOf(const avc::camera_t& camera) {
  try {
    CameraFromMessage(camera);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(CameraMessage, RoundTripKeepsEveryValue) {
  const camera::Camera camera = CameraFromMessage(GoodCamera());
  const avc::camera_t back = CameraToMessage(camera, "view_3", "cam0");
  EXPECT_EQ(back.image_id, "view_3");
  EXPECT_EQ(back.camera_id, "cam0");
  EXPECT_EQ(back.width, 320);
  EXPECT_EQ(back.cx, 159.5);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(back.distortion[i], GoodCamera().distortion[i]);
  for (int i = 0; i < 16; ++i) EXPECT_EQ(back.T_cam_world[i], GoodCamera().T_cam_world[i]) << i;
}

TEST(CameraMessage, TakesRigidCamerasAndRefusesBadOnesByField) {
  const camera::Camera camera = CameraFromMessage(GoodCamera());
  EXPECT_EQ(camera.intrinsics.width, 320);
  EXPECT_EQ(camera.intrinsics.distortion[0], -0.1);
  EXPECT_EQ(camera.T_cam_world.translation(), Eigen::Vector3d(0.1, 0.2, 0.3));

  avc::camera_t bad = GoodCamera();
  bad.fx = std::nan("");
  EXPECT_NE(ErrorOf(bad).find("camera of image 'view_3': focal"), std::string::npos)
      << ErrorOf(bad);
  bad = GoodCamera();
  bad.fy = INFINITY;
  EXPECT_NE(ErrorOf(bad).find("focal lengths are not finite"), std::string::npos);
  bad = GoodCamera();
  bad.width = 0;
  EXPECT_NE(ErrorOf(bad).find("image size 0x240"), std::string::npos);
  bad = GoodCamera();
  bad.distortion[4] = std::nan("");
  EXPECT_NE(ErrorOf(bad).find("distortion"), std::string::npos);
  bad = GoodCamera();
  bad.T_cam_world[7] = std::nan("");
  EXPECT_NE(ErrorOf(bad).find("T_cam_world is not finite"), std::string::npos);
  bad = GoodCamera();
  for (int c = 0; c < 3; ++c) bad.T_cam_world[c] *= 1.01;  // scaled row
  EXPECT_NE(ErrorOf(bad).find("not a rigid transform"), std::string::npos);
  bad = GoodCamera();
  for (int c = 0; c < 3; ++c) bad.T_cam_world[c] = -bad.T_cam_world[c];  // a reflection
  EXPECT_NE(ErrorOf(bad).find("not a rigid transform"), std::string::npos);
  bad = GoodCamera();
  bad.T_cam_world[12] = 0.5;
  EXPECT_NE(ErrorOf(bad).find("not a rigid transform"), std::string::npos);
}

}  // namespace
}  // namespace avc::messages
