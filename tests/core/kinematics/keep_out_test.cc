// Keep-out volumes: the fixed cylinder, and the plant's swept profile built from proxy voxels.

#include "core/kinematics/keep_out.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/kinematics/plant_keep_out.h"

namespace avc::kinematics {
namespace {

constexpr double kVoxel = 0.01;
constexpr double kMargin = 0.02;

// A plant-like voxel set: a stem 2 cm across up to 30 cm and one leaf reaching 15 cm out at
// 10-12 cm height, off to one side.
std::vector<Eigen::Vector3f> PlantVoxels() {
  std::vector<Eigen::Vector3f> voxels;
  for (float z = 0.005f; z < 0.30f; z += kVoxel) voxels.emplace_back(0.005f, 0.005f, z);
  for (float x = 0.005f; x < 0.15f; x += kVoxel) {
    for (float z = 0.105f; z < 0.12f; z += kVoxel) voxels.emplace_back(x, 0.03f, z);
  }
  return voxels;
}

Eigen::Isometry3d TiltedTable() {
  Eigen::Isometry3d T(
      Eigen::AngleAxisd(4 * std::numbers::pi / 180, Eigen::Vector3d(1, 2, 0).normalized()));
  T.translation() = Eigen::Vector3d(0.5, -0.1, -0.25);
  return T;
}

TEST(PlantKeepOut, HoldsEveryVoxelCornerAtEveryTableAngleWithTheMargin) {
  const Eigen::Isometry3d T_base_table = TiltedTable();
  const PlantKeepOut k = PlantKeepOutFromVoxels(PlantVoxels(), kVoxel, T_base_table, kMargin);
  ASSERT_TRUE(k.Validate().empty()) << k.Validate();
  int checked = 0;
  for (int step = 0; step < 360; step += 3) {
    const Eigen::Isometry3d T_base_world =
        T_base_table * Eigen::AngleAxisd(step * std::numbers::pi / 180, Eigen::Vector3d::UnitZ());
    for (const Eigen::Vector3f& c : PlantVoxels()) {
      for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d offset((corner & 1 ? 0.5 : -0.5) * kVoxel,
                                     (corner & 2 ? 0.5 : -0.5) * kVoxel,
                                     (corner & 4 ? 0.5 : -0.5) * kVoxel);
        const Eigen::Vector3d p = T_base_world * (c.cast<double>() + offset);
        ASSERT_TRUE(k.Contains(p)) << "voxel corner at " << step << " deg";
        // The margin holds outwards: a point 19 mm beyond the corner, away from the axis.
        const Eigen::Vector3d out_table = T_base_table.inverse() * p;
        Eigen::Vector3d radial(out_table.x(), out_table.y(), 0);
        const Eigen::Vector3d beyond = out_table + 0.019 * radial.normalized();
        EXPECT_TRUE(k.Contains(T_base_table * beyond));
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 120 * 8 * static_cast<int>(PlantVoxels().size()));
}

TEST(PlantKeepOut, FollowsTheProfileNotTheBoundingCylinder) {
  const Eigen::Isometry3d T_base_table = TiltedTable();
  const PlantKeepOut k = PlantKeepOutFromVoxels(PlantVoxels(), kVoxel, T_base_table, kMargin);
  const auto at = [&](double radius, double z) {
    return T_base_table * Eigen::Vector3d(radius, 0, z);
  };
  // Beside the leaf (any azimuth: it sweeps): kept out up to its reach + margin.
  const double leaf_reach = std::hypot(0.145, 0.03) + kVoxel / std::sqrt(2.0) + kMargin;
  EXPECT_TRUE(k.Contains(at(leaf_reach - 0.005, 0.11)));
  EXPECT_FALSE(k.Contains(at(leaf_reach + 0.005, 0.11)));
  // Above the leaf only the stem counts: 10 cm from the axis is free at 25 cm, where a
  // bounding cylinder of the whole plant would refuse it.
  EXPECT_FALSE(k.Contains(at(0.10, 0.25)));
  EXPECT_TRUE(k.Contains(at(0.02, 0.25)));
  // Above the top plus margin (rounded up to a whole slab at most), and below the bottom minus
  // margin: free.
  EXPECT_FALSE(k.Contains(at(0.0, 0.30 + kMargin + k.slab_m + 0.002)));
  EXPECT_FALSE(k.Contains(at(0.0, -kMargin - 0.005)));
  EXPECT_TRUE(k.Contains(at(0.0, 0.30 + kMargin - 0.005)));
  EXPECT_EQ(k.RadiusAt(at(0.0, 1.0)), 0);
}

TEST(PlantKeepOut, NoVoxelsKeepNothingOutAndBadInputIsRefused) {
  const PlantKeepOut none = PlantKeepOutFromVoxels({}, kVoxel, TiltedTable(), kMargin);
  EXPECT_TRUE(none.empty());
  EXPECT_TRUE(none.Validate().empty());
  EXPECT_FALSE(none.Contains(TiltedTable().translation()));
  EXPECT_THROW(PlantKeepOutFromVoxels(PlantVoxels(), 0, TiltedTable(), kMargin),
               std::invalid_argument);
  EXPECT_THROW(PlantKeepOutFromVoxels(PlantVoxels(), kVoxel, TiltedTable(), -0.01),
               std::invalid_argument);
  EXPECT_THROW(PlantKeepOutFromVoxels({Eigen::Vector3f(0, 0, std::nanf(""))}, kVoxel, TiltedTable(),
                                      kMargin),
               std::invalid_argument);
  // 30 m of plant in 2 cm slabs is beyond the message's limit.
  EXPECT_THROW(PlantKeepOutFromVoxels({Eigen::Vector3f(0, 0, 0), Eigen::Vector3f(0, 0, 30)}, kVoxel,
                                      TiltedTable(), kMargin),
               std::invalid_argument);

  PlantKeepOut k = PlantKeepOutFromVoxels(PlantVoxels(), kVoxel, TiltedTable(), kMargin);
  k.radius_m[3] = -0.1;
  EXPECT_NE(k.Validate().find("slab 3"), std::string::npos);
  k.radius_m[3] = 0.1;
  k.slab_m = 0;
  EXPECT_NE(k.Validate().find("slab"), std::string::npos);
  k.slab_m = 0.02;
  k.T_base_table.linear() *= 2;  // not a rigid transform
  EXPECT_NE(k.Validate().find("rigid"), std::string::npos);
}

TEST(KeepOutCylinder, ContainsItsInsideAndValidatesItsFields) {
  KeepOutCylinder c{Eigen::Vector2d(0.5, 0.0), 0.2, -0.3, 0.1};
  EXPECT_TRUE(c.Validate().empty());
  EXPECT_TRUE(c.Contains(Eigen::Vector3d(0.6, 0.1, 0.0)));
  EXPECT_FALSE(c.Contains(Eigen::Vector3d(0.75, 0.0, 0.0)));
  EXPECT_FALSE(c.Contains(Eigen::Vector3d(0.5, 0.0, 0.2)));
  EXPECT_NEAR(c.RadialDistance(Eigen::Vector3d(0.5, 0.3, 9)), 0.3, 1e-12);
  c.radius_m = -1;
  EXPECT_NE(c.Validate().find("negative"), std::string::npos);
  c.radius_m = 0.1;
  c.z_min_m = 1;
  EXPECT_NE(c.Validate().find("empty"), std::string::npos);
  c.z_max_m = std::nan("");
  EXPECT_NE(c.Validate().find("non-finite"), std::string::npos);
}

}  // namespace
}  // namespace avc::kinematics
