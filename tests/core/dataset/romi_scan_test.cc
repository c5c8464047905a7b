// The ROMI scan layout on the shared real scan: cameras in millimetres converted to metres, the
// scanner's z-down world turned upright, images matched to poses; and broken index files.

#include <gtest/gtest.h>

#include <fstream>

#include "core/dataset/dataset_reader.h"
#include "core/dataset/romi_index.h"
#include "core/dataset/world_up.h"
#include "tests/support/test_support.h"

namespace avc::dataset {
namespace {

namespace fs = std::filesystem;

fs::path Romi() { return testing::SharedDataDir() / "romi_arabidopsis_scan"; }

TEST(RomiScan, ReadsTheSharedScanInMetresWithZUp) {
  EXPECT_EQ(DetectDatasetFormat(Romi()), "romi");
  const ViewSet set = ReadDataset(Romi(), {.load_masks = false, .stride = 6});
  ASSERT_EQ(set.views.size(), 12u);
  EXPECT_EQ(set.format, "romi");
  EXPECT_EQ(set.unit, "mm");
  EXPECT_DOUBLE_EQ(set.metres_per_unit, 1e-3);
  EXPECT_NE(set.orientation_note.find("-z"), std::string::npos) << set.orientation_note;
  EXPECT_EQ(set.views.front().name, "rgb-000.jpg");
  EXPECT_EQ(set.views.front().image.cols, 1616);
  EXPECT_EQ(set.views.front().camera.intrinsics.height, 1080);
  // The plant's tip in the scanner's file (mm, z down), as its reference mesh places it.
  const Eigen::Vector3d tip = set.FileToWorld() * Eigen::Vector3d(375, 400, -19);
  EXPECT_NEAR(tip.z(), 0.019, 1e-12);
  for (const View& view : set.views) {
    // A ring about 0.35 m round the plant, every camera upright (image up is world +z).
    EXPECT_NEAR((view.camera.Centre() - tip).head<2>().norm(), 0.35, 0.05) << view.name;
    const Eigen::Vector3d image_up = -view.camera.T_cam_world.linear().row(1).transpose();
    EXPECT_GT(image_up.z(), 0.8) << view.name;
  }
  // ... and projects into the upper half of every image.
  for (const View& view : set.views) {
    const auto pixel = view.camera.Project(tip);
    ASSERT_TRUE(pixel.has_value()) << view.name;
    EXPECT_GT(pixel->y(), 0) << view.name;
    EXPECT_LT(pixel->y(), 540) << view.name << ": the tip is in the image's upper half";
  }
}

TEST(RomiScan, NamesTheEntryOfABrokenIndex) {
  testing::TempDir dir;
  const auto expect_error = [&](const std::string& json, const std::string& expected) {
    std::ofstream(dir / "index.json") << json;
    try {
      ReadRomiIndex(dir / "index.json");
      FAIL() << "accepted " << json;
    } catch (const std::runtime_error& error) {
      EXPECT_NE(std::string(error.what()).find(expected), std::string::npos) << error.what();
    }
  };
  expect_error("{", "not valid JSON");
  expect_error(R"({"camera": {"params": [1, 2]}})", "no camera.params and camera.poses");
  const std::string params = R"({"camera": {"params": [1000, 1000, 800, 540], "poses": [)";
  expect_error(params + R"({"rotmat": [[1,0,0],[0,1,0],[0,0,2]], "tvec": [0,0,1],
               "photoUri": "a/rgb-000.jpg"}]}})",
               "camera.poses[0]: rotmat is not a rotation");
  expect_error(params + R"({"rotmat": [[1,0,0],[0,1,0],[0,0,1]], "tvec": [0,0]}]}})",
               "camera.poses[0]: tvec must hold 3 numbers");
  expect_error(params + R"({"rotmat": [[1,0,0],[0,1,0],[0,0,1]], "tvec": [0,0,1],
               "photoUri": "x/a.jpg"}, {"rotmat": [[1,0,0],[0,1,0],[0,0,1]], "tvec": [0,0,1],
               "photoUri": "y/a.jpg"}]}})",
               "two poses name the image 'a.jpg'");
  EXPECT_TRUE(IsRomiScan(dir.path()));
  std::ofstream(dir / "index.json") << R"({"camera": {}})";
  EXPECT_FALSE(IsRomiScan(dir.path()));
}

camera::Camera Looking(const Eigen::Matrix3d& r) {
  camera::Camera camera;
  camera.intrinsics = {64, 48, 60, 60, 31.5, 23.5, {}};
  camera.T_cam_world.linear() = r;
  return camera;
}

TEST(WorldUp, TurnsOnlyWhenTheCamerasAgreeOnAnotherUp) {
  // Camera rows: x right, y down, z forward. Looking along +x with image up +z: no turn.
  Eigen::Matrix3d upright;
  upright << 0, -1, 0, 0, 0, -1, 1, 0, 0;
  EXPECT_FALSE(FindUprightTurn({Looking(upright), Looking(upright)}).has_value());
  EXPECT_TRUE(CamerasAgreeZIsUp({Looking(upright), Looking(upright)}));
  // The same cameras in a world whose up is -z.
  Eigen::Matrix3d flipped = upright * Eigen::Vector3d(1, -1, -1).asDiagonal();
  const auto turn = FindUprightTurn({Looking(flipped), Looking(flipped)});
  ASSERT_TRUE(turn.has_value());
  EXPECT_EQ(turn->from_axis, "-z");
  EXPECT_TRUE(((turn->rotation * -Eigen::Vector3d::UnitZ()) - Eigen::Vector3d::UnitZ()).isZero());
  // Up along +y (a y-up mesh tool's world): a quarter turn with exact entries.
  Eigen::Matrix3d y_up;
  y_up << 1, 0, 0, 0, -1, 0, 0, 0, -1;
  const auto quarter = FindUprightTurn({Looking(y_up)});
  ASSERT_TRUE(quarter.has_value());
  EXPECT_EQ(quarter->from_axis, "+y");
  EXPECT_EQ(quarter->rotation * Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ());
  // Cameras that disagree (half of them upside down) give no turn.
  Eigen::Matrix3d upside_down = Eigen::Vector3d(-1, -1, 1).asDiagonal() * flipped;
  EXPECT_FALSE(FindUprightTurn({Looking(flipped), Looking(upside_down)}).has_value());
  EXPECT_FALSE(CamerasAgreeZIsUp({Looking(flipped), Looking(upside_down)}));
  EXPECT_FALSE(CamerasAgreeZIsUp({Looking(flipped)}));
}

}  // namespace
}  // namespace avc::dataset
