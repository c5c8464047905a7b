// Every service's option table (and avc scan's): its configuration in force reads back to itself
// (so a scan's config/ or a log's CONFIG reproduces the service), every option says what it is, and
// the values that need a text form of their own survive the round trip.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "drivers/camera/camera_service_options.h"
#include "drivers/robot/robot_options.h"
#include "drivers/turntable/turntable_options.h"
#include "orchestrator/scan_options.h"
#include "services/builder/builder_options.h"
#include "services/calibrator/calibrator_options.h"
#include "services/clusterer/clusterer_options.h"
#include "services/planner/plan_settings.h"
#include "services/surfacer/surfacer_options.h"

namespace avc::config {
namespace {

template <typename Options>
void ExpectRoundTrip(const OptionTable<Options>& table, const Options& options) {
  const std::string text = table.ToToml(options);
  const auto file = std::filesystem::path(::testing::TempDir()) / (table.owner() + ".toml");
  std::ofstream(file) << text;
  EXPECT_EQ(table.ToToml(table.Load(Options{}, {file.string()}, {})), text) << table.owner();
  const std::string reference = table.Reference(Options{});
  EXPECT_EQ(reference.find("\n      \n"), std::string::npos)
      << table.owner() << ": an option without a doc line\n"
      << reference;
  EXPECT_GE(table.Names().size(), 2u);
}

TEST(ServiceOptions, EveryServicesConfigurationReadsBackToItself) {
  ExpectRoundTrip(builder::BuilderOptionTable(), builder::ReconstructOptions{});
  ExpectRoundTrip(clusterer::ClustererOptionTable(), clusterer::ClustererOptions{});
  ExpectRoundTrip(surfacer::SurfacerOptionTable(), surfacer::SurfacerOptions{});
  ExpectRoundTrip(planner::PlanOptionTable(), planner::PlanSettings{});
  ExpectRoundTrip(turntable::TurntableOptionTable(), turntable::TurntableNodeOptions{});
  ExpectRoundTrip(camera_driver::CameraOptionTable(), camera_driver::CameraServiceOptions{});
  ExpectRoundTrip(calibrator::CalibratorOptionTable(), calibrator::CalibratorNodeOptions{});
  ExpectRoundTrip(orchestrator::ScanOptionTable(), orchestrator::ScanOptions{});

  robot::RobotNodeConfig robot;
  ExpectRoundTrip(robot::RobotOptionTable(), robot);
  robot::RobotOptionTable().ApplyTexts(
      robot, {"envelope.table_z=-0.05", "envelope.keep_out=0.6 0 0.25 -0.1 0.2", "host=10.0.0.2"},
      "--set");
  ASSERT_TRUE(robot.envelope.keep_out.has_value());
  EXPECT_DOUBLE_EQ(robot.envelope.keep_out->radius_m, 0.25);
  EXPECT_EQ(robot.envelope.table_z_base_m, -0.05);
  ExpectRoundTrip(robot::RobotOptionTable(), robot);
  const std::string text = robot::RobotOptionTable().ToToml(robot);
  EXPECT_NE(text.find("keep_out = '0.6 0 0.25 -0.1 0.2'"), std::string::npos) << text;
  EXPECT_NE(text.find("host = '10.0.0.2'"), std::string::npos) << text;
  // An envelope the driver could not enforce is refused before the driver starts.
  EXPECT_THROW(
      robot::RobotOptionTable().ApplyTexts(robot, {"envelope.keep_out=0 0 0.2 0.5 0.1"}, "--set"),
      ConfigError);
}

}  // namespace
}  // namespace avc::config
