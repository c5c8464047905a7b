// The soil level (services/builder/soil_level.h) on rendered views of a textured horizontal
// plane: the sweep finds the plane's height from a proxy base several millimetres off it, and
// finds nothing on a plain plane or without a proxy.

#include "services/builder/soil_level.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "tests/core/eval/test_scenes.h"

namespace avc::builder {
namespace {

constexpr double kSoilZ = 0.118;       // m
constexpr double kStemRadius = 0.004;  // m: the stem hides the soil next to the axis

// Value noise on a 0.8 mm lattice: a grainy texture without repeats.
double Grain(double x, double y) {
  constexpr double kCell = 0.0008;
  const double gx = x / kCell;
  const double gy = y / kCell;
  const auto lattice = [](int64_t i, int64_t j) {
    uint64_t h = static_cast<uint64_t>(i) * 0x9E3779B97F4A7C15ull ^
                 static_cast<uint64_t>(j) * 0xC2B2AE3D27D4EB4Full;
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 32;
    return static_cast<double>(h % 1000) / 1000.0;
  };
  const int64_t i = static_cast<int64_t>(std::floor(gx));
  const int64_t j = static_cast<int64_t>(std::floor(gy));
  const double fx = gx - i;
  const double fy = gy - j;
  return (1 - fy) * ((1 - fx) * lattice(i, j) + fx * lattice(i + 1, j)) +
         fy * ((1 - fx) * lattice(i, j + 1) + fx * lattice(i + 1, j + 1));
}

// A view of the plane z = kSoilZ (textured or plain grey) by ray casting, with the stem's
// footprint as plant in its mask.
dataset::View RenderView(const camera::Camera& camera, bool textured) {
  const camera::Intrinsics& k = camera.intrinsics;
  dataset::View view;
  view.camera = camera;
  view.image = cv::Mat(k.height, k.width, CV_8UC3, cv::Scalar(90, 90, 90));
  view.mask = cv::Mat(k.height, k.width, CV_8UC1, cv::Scalar(0));
  eval::test::ForEachPlaneHit(camera, kSoilZ, [&](int row, int column, const Eigen::Vector3d& hit) {
    if (hit.head<2>().norm() <= kStemRadius) {
      view.mask.at<uint8_t>(row, column) = 255;
      return;
    }
    const double grey = textured ? 60.0 + 120.0 * Grain(hit.x(), hit.y()) : 110.0;
    view.image.at<cv::Vec3b>(row, column) = cv::Vec3b::all(static_cast<uint8_t>(grey));
  });
  return view;
}

// Twelve views round the axis from above at 40 and 65 degrees elevation, 0.25 m away.
std::vector<dataset::View> SoilViews(bool textured) {
  std::vector<dataset::View> views;
  for (int k = 0; k < 12; ++k) {
    const double elevation = (k % 2 == 0 ? 40.0 : 65.0) * std::numbers::pi / 180.0;
    const double azimuth = 2.0 * std::numbers::pi * k / 12.0;
    const Eigen::Vector3d target(0.0, 0.0, kSoilZ);
    const Eigen::Vector3d offset =
        0.25 * Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth),
                               std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
    views.push_back(RenderView(
        eval::test::LookAt(target + offset, target, Eigen::Vector3d::UnitZ()), textured));
  }
  return views;
}

// A proxy column on the axis whose base is `base_offset` above the soil.
mvs::MvsBounds StemProxy(double base_offset) {
  mvs::MvsBounds proxy;
  proxy.voxel_size = 0.002;
  for (double z = kSoilZ + base_offset + 0.001; z < kSoilZ + 0.08; z += 0.002) {
    proxy.occupied_centres.emplace_back(0.001f, -0.001f, static_cast<float>(z));
  }
  return proxy;
}

TEST(SoilLevel, FindsTheTexturedPlaneFromAProxyBaseAboveIt) {
  const std::vector<dataset::View> views = SoilViews(true);
  for (double offset : {0.012, -0.005}) {
    const std::optional<SoilLevel> soil = FindSoilLevel(views, StemProxy(offset));
    ASSERT_TRUE(soil.has_value()) << "proxy base " << offset;
    EXPECT_NEAR(soil->z, kSoilZ, 0.0005) << "proxy base " << offset;
    EXPECT_LT(soil->contrast, 0.6);
    EXPECT_GE(soil->patches, 100u);
  }
}

TEST(SoilLevel, APlainPlaneGivesNoLevelAndSaysWhy) {
  std::string why;
  EXPECT_FALSE(FindSoilLevel(SoilViews(false), StemProxy(0.01), {}, &why).has_value());
  // Plain patches have no say, so no plane gathers enough of them.
  EXPECT_NE(why.find("0 planes round the proxy's base had 100 textured patches"), std::string::npos)
      << why;
}

TEST(SoilLevel, NoProxyOrDisabledGivesNoLevelAndSaysWhy) {
  const std::vector<dataset::View> views = SoilViews(true);
  std::string why;
  EXPECT_FALSE(FindSoilLevel(views, mvs::MvsBounds{}, {}, &why).has_value());
  EXPECT_EQ(why, "the proxy is empty");
  SoilLevelOptions options;
  options.enabled = false;
  EXPECT_FALSE(FindSoilLevel(views, StemProxy(0.01), options, &why).has_value());
  EXPECT_EQ(why, "the search is off (soil.enabled)");
  EXPECT_FALSE(FindSoilLevel({}, StemProxy(0.01), {}, &why).has_value());
  EXPECT_EQ(why, "0 views have a mask and an image; 3 needed");
}

TEST(SoilLevel, RoundTripsThroughItsFile) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("avc_soil_" + std::to_string(getpid()) + ".json");
  EXPECT_FALSE(ReadSoilLevel(file).has_value());
  {
    std::ofstream out(file);
    out << SoilLevelToJson({0.1234, 0.25, 321}).dump();
  }
  const std::optional<SoilLevel> soil = ReadSoilLevel(file);
  ASSERT_TRUE(soil.has_value());
  EXPECT_DOUBLE_EQ(soil->z, 0.1234);
  EXPECT_EQ(soil->patches, 321u);
  {
    std::ofstream out(file);
    out << "{\"z_m\": \"high\"}";
  }
  EXPECT_THROW(ReadSoilLevel(file), std::runtime_error);
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace avc::builder
