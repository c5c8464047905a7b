// The support under a plant, found in the proxy's slices: a stage or block under a thin stem is
// found at its top; a leaf whorl over a stem, a plant with no support or a disabled search is not.

#include "services/builder/support_level.h"

#include <gtest/gtest.h>

namespace avc::builder {
namespace {

constexpr double kVoxel = 0.002;

// Voxel centres filling a square of `side` voxels in each slice [first, last).
void AddSlab(std::vector<Eigen::Vector3f>& voxels, int first, int last, int side) {
  for (int z = first; z < last; ++z) {
    for (int y = 0; y < side; ++y) {
      for (int x = 0; x < side; ++x) {
        voxels.emplace_back((x + 0.5) * kVoxel, (y + 0.5) * kVoxel, (z + 0.5) * kVoxel);
      }
    }
  }
}

TEST(SupportLevel, FindsTheTopOfAStageUnderAThinStem) {
  std::vector<Eigen::Vector3f> voxels;
  AddSlab(voxels, -20, 0, 30);  // a stage, 40 mm thick
  AddSlab(voxels, 0, 100, 2);   // a stem 200 mm tall
  AddSlab(voxels, 60, 64, 5);   // a crown of branches: 6x the stem, not a support
  const auto support = FindSupportTop(voxels, kVoxel);
  ASSERT_TRUE(support.has_value());
  EXPECT_NEAR(support->z, 0.0, 1e-9);
  EXPECT_NEAR(support->jump, 900.0 / 4.0, 1e-9);
  EXPECT_GT(support->mass_fraction, 0.9);
  EXPECT_NE(DescribeSupport(*support).find("top at z = 0.0 mm"), std::string::npos);
}

TEST(SupportLevel, LeavesALeafWhorlAndAPlantWithoutSupportAlone) {
  std::vector<Eigen::Vector3f> whorl;
  AddSlab(whorl, 0, 60, 2);    // stem
  AddSlab(whorl, 60, 62, 20);  // a whorl of leaves on top: big slices above, not below
  EXPECT_FALSE(FindSupportTop(whorl, kVoxel).has_value());
  std::vector<Eigen::Vector3f> rosette;
  AddSlab(rosette, 0, 3, 25);  // a rosette at the base holds most voxels ...
  AddSlab(rosette, 3, 80, 2);  // ... under a thin inflorescence
  SupportOptions strict;
  strict.min_mass_fraction = 0.99;  // ... but not 99 % of them
  EXPECT_FALSE(FindSupportTop(rosette, kVoxel, strict).has_value());
  EXPECT_FALSE(FindSupportTop({}, kVoxel).has_value());
  SupportOptions disabled;
  disabled.enabled = false;
  std::vector<Eigen::Vector3f> staged;
  AddSlab(staged, -20, 0, 30);
  AddSlab(staged, 0, 100, 2);
  EXPECT_FALSE(FindSupportTop(staged, kVoxel, disabled).has_value());
}

TEST(SupportLevel, RefusesBadOptions) {
  SupportOptions options;
  options.min_jump = 1;
  EXPECT_THROW(FindSupportTop({}, kVoxel, options), std::invalid_argument);
  options = {};
  options.min_mass_fraction = 1.5;
  EXPECT_NE(options.Validate().find("min_mass_fraction"), std::string::npos);
  options = {};
  options.min_plant_slices = 0;
  EXPECT_NE(options.Validate().find("min_plant_slices"), std::string::npos);
  EXPECT_EQ(SupportOptions{}.Validate(), "");
}

}  // namespace
}  // namespace avc::builder
