// Views realised in the nominal cell: the camera lands where it was asked, looking at the target,
// on the turntable angle that faces the arm; views the arm cannot reach, below the table or in
// the plant's box are refused, and bad input throws. With the arm driver's envelope, a view whose
// joint move it would refuse is not realised.

#include "services/planner/cell_view.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "sim/cell/cell_fixtures.h"
#include "sim/cell/view_selection.h"

namespace avc::planner {
namespace {

const Eigen::Vector3d kAim(0, 0, 0.12);

Eigen::Vector3d Eye(double distance, double elevation_deg, double azimuth_deg) {
  const double e = elevation_deg * M_PI / 180;
  const double a = azimuth_deg * M_PI / 180;
  return kAim + distance * Eigen::Vector3d(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a),
                                           std::sin(e));
}

TEST(RealiseView, TheCameraIsWhereAskedAndLooksAtTheTarget) {
  const sim::CellTruth cell = sim::NominalCell();
  kinematics::JointVector joints = sim::StartJoints(cell);
  for (const double azimuth : {0.0, 90.0, 200.0, 315.0}) {
    for (const double elevation : {15.0, 45.0}) {
      const auto view = RealiseView(cell, Eye(0.45, elevation, azimuth), kAim, {}, joints);
      ASSERT_TRUE(view.has_value()) << "azimuth " << azimuth << " elevation " << elevation;
      EXPECT_LT((view->centre_world - Eye(0.45, elevation, azimuth)).norm(), 1e-6);
      const auto pixel = view->camera.Project(kAim);
      ASSERT_TRUE(pixel.has_value());
      const camera::Intrinsics& k = view->camera.intrinsics;
      // The optical axis passes through the target: it images at the principal point.
      EXPECT_NEAR(pixel->x(), k.cx, 1.0);
      EXPECT_NEAR(pixel->y(), k.cy, 1.0);
      joints = view->joints;
    }
  }
}

TEST(RealiseView, RefusesWhatTheCellCannotDo) {
  const sim::CellTruth cell = sim::NominalCell();
  const kinematics::JointVector joints = sim::StartJoints(cell);
  EXPECT_FALSE(RealiseView(cell, Eye(3.0, 30, 0), kAim, {}, joints).has_value());   // out of reach
  EXPECT_FALSE(RealiseView(cell, Eye(0.4, -30, 0), kAim, {}, joints).has_value());  // under table
  const Eigen::AlignedBox3d plant(Eigen::Vector3d(-0.1, -0.1, 0), Eigen::Vector3d(0.1, 0.1, 0.3));
  EXPECT_FALSE(RealiseView(cell, Eye(0.12, 10, 0), kAim, plant, joints).has_value());  // inside
  EXPECT_THROW(RealiseView(cell, Eigen::Vector3d(NAN, 0, 0), kAim, {}, joints),
               std::invalid_argument);
  EXPECT_THROW(RealiseView(cell, kAim, kAim, {}, joints), std::invalid_argument);
}

TEST(RealiseView, KeepsToTheDriversEnvelope) {
  const sim::CellTruth cell = sim::NominalCell();
  const kinematics::JointVector start = sim::StartJoints(cell);
  ReachOptions reach;
  reach.envelope = kinematics::PlanningEnvelope(sim::FixturesEnvelope(cell));
  // A low view over the bench: the move there passes the envelope from the start joints.
  const auto low = RealiseView(cell, Eye(0.45, 15, 0), kAim, {}, start, reach);
  ASSERT_TRUE(low.has_value());
  EXPECT_EQ(kinematics::CheckJointMove(*reach.envelope, cell.dh, start, low->joints, 1.0, 1.0), "");
  // Raise the bench to the camera's height: the flange would be under it, so the same view is no
  // longer realised, though the arm reaches it without the envelope.
  ReachOptions raised = reach;
  raised.envelope->table_z_base_m = (cell.T_base_table * Eye(0.45, 15, 0)).z();
  EXPECT_FALSE(RealiseView(cell, Eye(0.45, 15, 0), kAim, {}, start, raised).has_value());
  EXPECT_TRUE(RealiseView(cell, Eye(0.45, 15, 0), kAim, {}, start).has_value());
  // Nor when the keep-out cylinder about the turntable is made wide and tall enough to hold the
  // flange at that view.
  ReachOptions wide = reach;
  wide.envelope->keep_out->radius_m = 0.6;
  wide.envelope->keep_out->z_max_m = 2.0;
  EXPECT_FALSE(RealiseView(cell, Eye(0.45, 15, 0), kAim, {}, start, wide).has_value());
}

}  // namespace
}  // namespace avc::planner
