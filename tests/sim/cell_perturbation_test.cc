#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "sim/cell/cell_truth_json.h"
#include "sim/cell/perturbation.h"

namespace avc::sim {
namespace {

double RotationAngle(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return Eigen::AngleAxisd(Eigen::Matrix3d(a * b.transpose())).angle();
}

TEST(PerturbedCell, SameSeedGivesTheSameCell) {
  EXPECT_EQ(CellTruthToJson(PerturbedCell(17)).dump(), CellTruthToJson(PerturbedCell(17)).dump());
  EXPECT_NE(CellTruthToJson(PerturbedCell(17)).dump(), CellTruthToJson(PerturbedCell(18)).dump());
  const CellTruth a = PerturbedCell(99), b = PerturbedCell(99);
  EXPECT_EQ(a.dh.a, b.dh.a);
  EXPECT_EQ(a.T_flange_cam.matrix(), b.T_flange_cam.matrix());
  EXPECT_EQ(a.intrinsics.distortion, b.intrinsics.distortion);
}

TEST(PerturbedCell, StaysWithinTheScalesAndUsesThem) {
  const PerturbationScales scales;
  const CellTruth nominal = NominalCell();
  const Eigen::Isometry3d nominal_table_base = nominal.T_base_table.inverse();
  double largest_dh_length = 0, largest_tilt = 0, largest_base_rotation = 0, largest_focal = 0;
  for (uint32_t seed = 0; seed < 100; ++seed) {
    const CellTruth cell = PerturbedCell(seed, scales);
    ASSERT_EQ(cell.Validate(), "");
    for (int i = 0; i < 6; ++i) {
      EXPECT_LE(std::abs(cell.dh.a[i] - nominal.dh.a[i]), scales.dh_length_m);
      EXPECT_LE(std::abs(cell.dh.d[i] - nominal.dh.d[i]), scales.dh_length_m);
      EXPECT_LE(std::abs(cell.dh.alpha[i] - nominal.dh.alpha[i]), scales.dh_alpha_rad);
      EXPECT_LE(std::abs(cell.dh.theta_offset[i] - nominal.dh.theta_offset[i]),
                scales.dh_theta_offset_rad);
      largest_dh_length = std::max(largest_dh_length, std::abs(cell.dh.a[i] - nominal.dh.a[i]));
    }
    const Eigen::Isometry3d table_base = cell.T_base_table.inverse();
    const double base_rotation = RotationAngle(table_base.linear(), nominal_table_base.linear());
    EXPECT_LE(base_rotation, scales.base_rotation_rad + 1e-12);
    largest_base_rotation = std::max(largest_base_rotation, base_rotation);
    EXPECT_LE((table_base.translation() - nominal_table_base.translation()).cwiseAbs().maxCoeff(),
              scales.base_translation_m + 1e-12);
    const double tilt = std::acos(std::min(1.0, cell.turntable_axis_table.z()));
    EXPECT_LE(tilt, scales.axis_tilt_rad + 1e-12);
    largest_tilt = std::max(largest_tilt, tilt);
    EXPECT_NEAR(cell.turntable_axis_table.norm(), 1.0, 1e-15);
    EXPECT_LE(cell.turntable_centre_table.head<2>().cwiseAbs().maxCoeff(), scales.centre_offset_m);
    EXPECT_EQ(cell.turntable_centre_table.z(), 0.0);
    EXPECT_LE(RotationAngle(cell.T_flange_cam.linear(), nominal.T_flange_cam.linear()),
              scales.hand_eye_rotation_rad + 1e-12);
    EXPECT_LE((cell.T_flange_cam.translation() - nominal.T_flange_cam.translation())
                  .cwiseAbs()
                  .maxCoeff(),
              scales.hand_eye_translation_m + 1e-12);
    const double focal = std::abs(cell.intrinsics.fx / nominal.intrinsics.fx - 1);
    EXPECT_LE(focal, scales.focal_relative + 1e-12);
    EXPECT_LE(std::abs(cell.intrinsics.fy / nominal.intrinsics.fy - 1),
              scales.focal_relative + 1e-12);
    largest_focal = std::max(largest_focal, focal);
    EXPECT_LE(std::abs(cell.intrinsics.cx - nominal.intrinsics.cx), scales.principal_point_px);
    EXPECT_LE(std::abs(cell.intrinsics.cy - nominal.intrinsics.cy), scales.principal_point_px);
    const auto& k = cell.intrinsics.distortion;
    const auto& k0 = nominal.intrinsics.distortion;
    EXPECT_LE(std::abs(k[0] - k0[0]), scales.k1_k2);
    EXPECT_LE(std::abs(k[1] - k0[1]), scales.k1_k2);
    EXPECT_LE(std::abs(k[2] - k0[2]), scales.p1_p2);
    EXPECT_LE(std::abs(k[3] - k0[3]), scales.p1_p2);
    EXPECT_LE(std::abs(k[4] - k0[4]), scales.k3);
  }
  // Uniform draws over 100 cells come close to the bounds.
  EXPECT_GT(largest_dh_length, 0.9 * scales.dh_length_m);
  EXPECT_GT(largest_tilt, 0.9 * scales.axis_tilt_rad);
  EXPECT_GT(largest_base_rotation, 0.9 * scales.base_rotation_rad);
  EXPECT_GT(largest_focal, 0.9 * scales.focal_relative);
}

TEST(PerturbedCell, DiffersFromNominalEverywhere) {
  const CellTruth nominal = NominalCell();
  const CellTruth cell = PerturbedCell(3);
  for (int i = 0; i < 6; ++i) {
    EXPECT_NE(cell.dh.a[i], nominal.dh.a[i]);
    EXPECT_NE(cell.dh.d[i], nominal.dh.d[i]);
    EXPECT_NE(cell.dh.alpha[i], nominal.dh.alpha[i]);
    EXPECT_NE(cell.dh.theta_offset[i], nominal.dh.theta_offset[i]);
  }
  EXPECT_FALSE(cell.T_base_table.isApprox(nominal.T_base_table, 1e-6));
  EXPECT_FALSE(cell.T_flange_cam.isApprox(nominal.T_flange_cam, 1e-6));
  EXPECT_NE(cell.turntable_axis_table, nominal.turntable_axis_table);
  EXPECT_NE(cell.turntable_centre_table, nominal.turntable_centre_table);
  EXPECT_NE(cell.intrinsics.fx, nominal.intrinsics.fx);
  EXPECT_NE(cell.intrinsics.cy, nominal.intrinsics.cy);
  for (int i = 0; i < 5; ++i)
    EXPECT_NE(cell.intrinsics.distortion[i], nominal.intrinsics.distortion[i]);
}

TEST(PerturbedCell, ZeroScalesGiveTheNominalCell) {
  PerturbationScales none;
  none.dh_length_m = none.dh_alpha_rad = none.dh_theta_offset_rad = 0;
  none.base_translation_m = none.base_rotation_rad = none.axis_tilt_rad = none.centre_offset_m = 0;
  none.hand_eye_translation_m = none.hand_eye_rotation_rad = 0;
  none.focal_relative = none.principal_point_px = none.k1_k2 = none.k3 = none.p1_p2 = 0;
  const CellTruth cell = PerturbedCell(5, none);
  const CellTruth nominal = NominalCell();
  EXPECT_EQ(cell.dh.a, nominal.dh.a);
  EXPECT_EQ(cell.dh.alpha, nominal.dh.alpha);
  EXPECT_TRUE(cell.T_base_table.isApprox(nominal.T_base_table, 1e-15));
  EXPECT_TRUE(cell.T_flange_cam.isApprox(nominal.T_flange_cam, 1e-15));
  EXPECT_EQ(cell.turntable_axis_table, nominal.turntable_axis_table);
  EXPECT_EQ(cell.intrinsics.fx, nominal.intrinsics.fx);
}

TEST(PerturbedCell, RejectsInvalidScales) {
  PerturbationScales scales;
  scales.axis_tilt_rad = -0.1;
  try {
    PerturbedCell(1, scales);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("axis_tilt_rad"), std::string::npos) << error.what();
  }
  scales = {};
  scales.dh_length_m = std::nan("");
  EXPECT_THROW(PerturbedCell(1, scales), std::invalid_argument);
}

}  // namespace
}  // namespace avc::sim
