// The simulated cell's bench and turntable as a safety envelope: the table plane is the bench
// under the turntable top, the keep-out cylinder stands on the turntable axis, the arm's start
// pose is inside the envelope, and the avc robot arguments say exactly that.

#include "sim/cell/cell_fixtures.h"

#include <gtest/gtest.h>

#include "sim/cell/view_selection.h"

namespace avc::sim {
namespace {

TEST(CellFixtures, TheBenchAndTurntableOfTheNominalCell) {
  const CellTruth cell = NominalCell();
  const CellFixtures fixtures;
  const kinematics::SafetyEnvelope envelope = FixturesEnvelope(cell, fixtures);
  ASSERT_EQ(envelope.Validate(), "");
  const Eigen::Vector3d top_base = cell.T_base_table * Eigen::Vector3d::Zero();
  ASSERT_TRUE(envelope.table_z_base_m.has_value());
  EXPECT_NEAR(*envelope.table_z_base_m, top_base.z() - fixtures.turntable_height_m, 1e-12);
  EXPECT_NEAR(envelope.table_clearance_m, fixtures.clearance_m, 1e-12);
  ASSERT_TRUE(envelope.keep_out.has_value());
  EXPECT_NEAR((envelope.keep_out->centre_base - top_base.head<2>()).norm(), 0, 1e-12);
  EXPECT_NEAR(envelope.keep_out->centre_base.norm(), 0.55, 1e-6);  // the axis from the base
  EXPECT_NEAR(envelope.keep_out->radius_m, fixtures.turntable_radius_m + fixtures.clearance_m,
              1e-12);
  EXPECT_NEAR(envelope.keep_out->z_max_m, top_base.z() + fixtures.clearance_m, 1e-12);
  EXPECT_TRUE(envelope.keep_out->Contains(top_base - Eigen::Vector3d(0, 0, 0.01)));
  EXPECT_FALSE(envelope.keep_out->Contains(top_base + Eigen::Vector3d(0, 0, 0.05)));
  const kinematics::JointVector start = StartJoints(cell);
  EXPECT_EQ(kinematics::CheckJointMove(envelope, cell.dh, start, start, 1.0, 1.0), "");
}

TEST(CellFixtures, RobotArgumentsCarryTheEnvelope) {
  kinematics::SafetyEnvelope envelope;
  EXPECT_TRUE(RobotEnvelopeArguments(envelope).empty());
  envelope.table_z_base_m = -0.26;
  envelope.keep_out = kinematics::KeepOutCylinder{Eigen::Vector2d(0.55, -0.001), 0.2, -0.26, -0.18};
  EXPECT_EQ(
      RobotEnvelopeArguments(envelope),
      (std::vector<std::string>{"--table-z", "-0.2600", "--table-clearance", "0.0200", "--keep-out",
                                "0.5500", "-0.0010", "0.2000", "-0.2600", "-0.1800"}));
}

}  // namespace
}  // namespace avc::sim
