// Bad input gives an exception whose message names the problem, never a crash.

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <string>

#include "sim/render/renderer.h"
#include "tests/sim/render_test_scenes.h"

namespace avc::sim {
namespace {

Scene Square() {
  Scene scene;
  scene.name = "square";
  scene.materials = {render_test::TexturedMaterial(1)};
  render_test::AddQuad(&scene.mesh, {-0.1f, -0.1f, 0}, {0.2f, 0, 0}, {0, 0.2f, 0}, 2, 1, 0);
  return scene;
}

camera::Camera TopCamera() {
  camera::Camera camera;
  camera.intrinsics = render_test::TestIntrinsics(true, 160, 120);
  camera.T_cam_world = render_test::LookAt({0, 0, 0.5}, {0, 0, 0}, Eigen::Vector3d::UnitY());
  return camera;
}

// Runs Render and returns the message of the std::invalid_argument it must throw.
std::string RenderError(const Scene& scene, const camera::Camera& camera,
                        const RenderOptions& options = {}) {
  try {
    Render(scene, camera, options);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  ADD_FAILURE() << "Render accepted bad input";
  return {};
}

TEST(RenderInput, ValidSceneRenders) {
  const RenderResult result = Render(Square(), TopCamera(), RenderOptions{});
  EXPECT_GT(cv::countNonZero(result.labels == 1), 1000);
}

TEST(RenderInput, FaceWithInvalidVertexIndex) {
  Scene scene = Square();
  scene.mesh.faces[3] = Eigen::Vector3i(0, 1, 99);
  const std::string message = RenderError(scene, TopCamera());
  EXPECT_NE(message.find("scene 'square'"), std::string::npos) << message;
  EXPECT_NE(message.find("face 3 refers to vertex 99"), std::string::npos) << message;
}

TEST(RenderInput, NegativeVertexIndex) {
  Scene scene = Square();
  scene.mesh.faces[0] = Eigen::Vector3i(-1, 1, 2);
  EXPECT_NE(RenderError(scene, TopCamera()).find("face 0 refers to vertex -1"), std::string::npos);
}

TEST(RenderInput, MaterialIndexOutOfRange) {
  Scene scene = Square();
  scene.mesh.face_materials[5] = 4;
  const std::string message = RenderError(scene, TopCamera());
  EXPECT_NE(message.find("face 5 uses material 4 but the scene has 1 material"), std::string::npos)
      << message;
  scene.mesh.face_materials[5] = -2;
  EXPECT_NE(RenderError(scene, TopCamera()).find("material -2"), std::string::npos);
}

TEST(RenderInput, MissingAttributes) {
  Scene no_uvs = Square();
  no_uvs.mesh.uvs.clear();
  EXPECT_NE(RenderError(no_uvs, TopCamera()).find("no uvs"), std::string::npos);
  Scene no_materials = Square();
  no_materials.mesh.face_materials.clear();
  EXPECT_NE(RenderError(no_materials, TopCamera()).find("no face_materials"), std::string::npos);
  Scene short_labels = Square();
  short_labels.mesh.face_labels.pop_back();
  EXPECT_NE(RenderError(short_labels, TopCamera()).find("face_labels has 7 entries"),
            std::string::npos);
}

TEST(RenderInput, NonFiniteVertex) {
  Scene scene = Square();
  scene.mesh.vertices[2].y() = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NE(RenderError(scene, TopCamera()).find("vertex 2 is not finite"), std::string::npos);
}

TEST(RenderInput, InvalidIntrinsics) {
  camera::Camera camera = TopCamera();
  camera.intrinsics.fx = 0;
  std::string message = RenderError(Square(), camera);
  EXPECT_NE(message.find("intrinsics"), std::string::npos) << message;
  EXPECT_NE(message.find("fx=0"), std::string::npos) << message;
  camera = TopCamera();
  camera.intrinsics.width = -4;
  EXPECT_NE(RenderError(Square(), camera).find("image size -4x120"), std::string::npos);
  camera = TopCamera();
  camera.intrinsics.distortion[1] = std::numeric_limits<double>::infinity();
  EXPECT_NE(RenderError(Square(), camera).find("distortion"), std::string::npos);
}

TEST(RenderInput, DistortionThatFoldsOverInTheImage) {
  camera::Camera camera = TopCamera();
  camera.intrinsics.distortion = {-1.5, 0, 0, 0, 0};  // r (1 - 1.5 r^2) turns back at r = 0.47
  const std::string message = RenderError(Square(), camera);
  EXPECT_NE(message.find("folds over"), std::string::npos) << message;
}

TEST(RenderInput, BadPose) {
  camera::Camera camera = TopCamera();
  camera.T_cam_world.translation().x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(RenderError(Square(), camera).find("T_cam_world is not finite"), std::string::npos);
  camera = TopCamera();
  camera.T_cam_world.linear() *= 2.0;
  EXPECT_NE(RenderError(Square(), camera).find("not orthonormal"), std::string::npos);
}

TEST(RenderInput, BadOptions) {
  RenderOptions options;
  options.samples_per_pixel_axis = 0;
  EXPECT_NE(RenderError(Square(), TopCamera(), options).find("samples_per_pixel_axis 0"),
            std::string::npos);
  options = {};
  options.light_direction = Eigen::Vector3d::Zero();
  EXPECT_NE(RenderError(Square(), TopCamera(), options).find("light_direction"), std::string::npos);
  options = {};
  options.near_clip_m = -1;
  EXPECT_NE(RenderError(Square(), TopCamera(), options).find("near_clip_m"), std::string::npos);
  options = {};
  options.ambient = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NE(RenderError(Square(), TopCamera(), options).find("ambient"), std::string::npos);
}

TEST(RenderInput, EmptySceneIsAllBackground) {
  Scene scene;
  scene.name = "empty";
  const RenderResult result = Render(scene, TopCamera(), RenderOptions{});
  EXPECT_EQ(cv::countNonZero(result.labels), 0);
  EXPECT_EQ(cv::countNonZero(result.depth), 0);
}

TEST(RenderInput, GeometryBehindAndAcrossTheCameraIsClipped) {
  // A floor reaching from behind the camera to far ahead, seen at a grazing angle, plus a
  // square entirely behind: no crash, no wrapped-around triangles, depth never below the near
  // plane.
  Scene scene = Square();
  render_test::AddQuad(&scene.mesh, {-5, -5, -0.2f}, {10, 0, 0}, {0, 10, 0}, 3, 2, 0);
  render_test::AddQuad(&scene.mesh, {-0.1f, -0.1f, 2}, {0.2f, 0, 0}, {0, 0.2f, 0}, 1, 3, 0);
  camera::Camera camera = TopCamera();
  camera.T_cam_world = render_test::LookAt({0, -0.5, 0.1}, {0, 1, 0.0});
  const RenderResult result = Render(scene, camera, RenderOptions{});
  EXPECT_GT(result.stats.clipped_faces, 0u);
  EXPECT_EQ(cv::countNonZero(result.labels == 3), 0) << "the square behind the camera is drawn";
  double min_depth = 0, max_depth = 0;
  cv::minMaxLoc(result.depth, &min_depth, &max_depth, nullptr, nullptr, result.labels != 0);
  EXPECT_GE(min_depth, RenderOptions{}.near_clip_m);
  // The floor fills the lower half: no pixel there is background.
  EXPECT_EQ(cv::countNonZero(result.labels.rowRange(80, 120) == 0), 0);
}

}  // namespace
}  // namespace avc::sim
