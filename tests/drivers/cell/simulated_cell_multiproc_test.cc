// The whole simulated cell as a lab runs it: `avc sim cell` plus `avc robot`, `avc turntable`
// and `avc camera` as separate processes on real udpm:// URLs (inside the test's private network
// namespace), each driver on its real protocol (RTDE/URScript/dashboard, serial pty, PTP/IP via
// libgphoto2). The arm moves to a planned view, the table turns, the camera captures, and the
// image that arrives is exactly the plant rendered from the true camera pose of that moment,
// which is where the plan put it (within the cell's perturbations).

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <opencv2/imgcodecs.hpp>

#include "bench/devices/cell_processes.h"
#include "core/auth/command_key.h"
#include "core/bus/bus.h"
#include "core/bus/bus_options.h"
#include "core/camera/camera_io.h"
#include "core/launch/child_process.h"
#include "drivers/client/cell_client.h"
#include "sim/cell/cell_truth.h"
#include "sim/cell/view_selection.h"
#include "sim/dataset/render_dataset.h"
#include "sim/emulators/cell/simulated_cell.h"
#include "sim/render/renderer.h"
#include "tests/support/test_support.h"

namespace avc::bench {
namespace {

namespace fs = std::filesystem;
using std::chrono::milliseconds;

constexpr int kTriangles = 6000;

TEST(SimulatedCellMultiproc, PlannedViewIsCapturedFromTheTruePoseThroughEveryRealDriver) {
  testing::TempDir dir("avc-cell-mp");
  const bus::BusOptions bus_options = bus::ResolveBusOptions({}, "cell-test");
  CellProcessOptions options =
      CellOptionsOnBus(bus_options, testing::Executable("avc"), dir.path());
  options.time_scale = 10;
  options.triangles = kTriangles;
  options.width = 320;
  options.height = 240;
  options.png = true;  // lossless, so the delivered frame can be compared bit for bit
  options.stages = false;
  CellProcesses cell(options);

  bus::Bus bus(bus_options);
  bus::EventLoop loop;
  bus.AttachTo(loop);
  client::CellClient client(bus, loop, "avc-bench", cell.key());
  try {
    client.WaitReady({"avc-sim", "avc-robot", "avc-turntable", "avc-camera"}, milliseconds(20000));
    client.Robot(avc::robot_command_t::KIND_POWER_ON, milliseconds(10000));
    client.Robot(avc::robot_command_t::KIND_BRAKE_RELEASE, milliseconds(10000));

    const sim::CellTruth nominal = sim::NominalCell();
    const Eigen::Vector3d target(0, 0, 0.1);
    const Eigen::Vector3d planned_centre = sim::ViewpointOnSphere(
        target, 0.6, 25 * std::numbers::pi / 180, sim::RobotAzimuth(nominal));
    const auto q = sim::JointsLookingAt(nominal, planned_centre, target, client.last_joints());
    ASSERT_TRUE(q.has_value());
    client.MoveJoints(*q, milliseconds(20000));
    const double table_angle = std::numbers::pi / 2;
    client.TurntableGoto(table_angle, milliseconds(20000));
    const client::CapturedView view =
        client.Capture("view_0000", avc::image_t::ENCODING_PNG, milliseconds(20000));

    ASSERT_EQ(view.image.width, 320);
    ASSERT_EQ(view.image.height, 240);
    EXPECT_EQ(view.image.camera_id, "cam0");
    const cv::Mat delivered = cv::imdecode(view.image.data, cv::IMREAD_COLOR);
    ASSERT_FALSE(delivered.empty());

    // The frame is the plant rendered from the true camera the cell logged for it...
    const camera::Camera truth = sim::ReadTruthLog(cell.truth_log()).back().camera;
    sim::RenderDatasetOptions scene_options;
    scene_options.plant.target_triangles = kTriangles;
    scene_options.render.background.kind = sim::Background::Kind::kCloth;
    const sim::RenderResult expected =
        sim::Render(sim::MakeScene(scene_options), truth, scene_options.render);
    EXPECT_EQ(cv::norm(delivered, expected.color, cv::NORM_INF), 0);
    const double plant_pixels = cv::countNonZero(expected.labels);
    EXPECT_GT(plant_pixels, 0.05 * 320 * 240) << "the plant should fill part of the view";

    // ...and that camera stands where the plan put it, seen from the table frame at the
    // commanded angle (perturbed cell: mm-level kinematics, 0.05 deg table noise).
    const Eigen::Vector3d centre_table = sim::TableFromWorld(nominal, table_angle) * truth.Centre();
    EXPECT_LT((centre_table - planned_centre).norm(), 0.02)
        << "true centre " << centre_table.transpose() << " planned " << planned_centre.transpose();
  } catch (const std::exception& error) {
    FAIL() << error.what() << "\n" << cell.LogTails();
  }
  EXPECT_TRUE(cell.Exited().empty()) << cell.LogTails();
}

// The demo launch file as a user runs it (copied, with its own link dir): `avc up` brings the
// simulated cell, the three drivers and the recorder to READY, a capture goes through, and
// SIGTERM stops everything with exit 0.
TEST(SimulatedCellMultiproc, SimCellLaunchFileRunsTheCellUnderAvcUp) {
  testing::TempDir dir("avc-cell-up");
  std::string launch = testing::ReadFile(testing::SourceDir() / "launch" / "sim-cell.toml");
  for (size_t at; (at = launch.find("/tmp/avc-sim")) != std::string::npos;) {
    launch.replace(at, std::string("/tmp/avc-sim").size(), (dir / "sim").string());
  }
  testing::WriteFile(dir / "sim-cell.toml", launch);

  const bus::BusOptions bus_options = bus::ResolveBusOptions({}, "cell-up-test");
  launch::SpawnSpec spec;
  spec.argv = {testing::Executable("avc").string(), "up", (dir / "sim-cell.toml").string()};
  spec.log_file = (dir / "up.log").string();
  spec.env["HOME"] = dir.path().string();  // the camera driver's libgphoto2 settings
  // The drivers find the cell's key where a user's would be: AVC_KEY_DIR/<cell>.key.
  spec.env["AVC_KEY_DIR"] = (dir / "keys").string();
  const auth::CommandKey key = auth::GenerateCommandKey(dir / "keys" / (bus_options.cell + ".key"));
  launch::ChildProcess up = launch::ChildProcess::Spawn(spec);

  bus::Bus bus(bus_options);
  bus::EventLoop loop;
  bus.AttachTo(loop);
  client::CellClient client(bus, loop, "avc-bench", key);
  try {
    client.WaitReady({"avc-sim", "avc-robot", "avc-turntable", "avc-camera", "avc-record"},
                     milliseconds(30000));
    const client::CapturedView view =
        client.Capture("demo_0000", avc::image_t::ENCODING_JPEG, milliseconds(20000));
    EXPECT_EQ(view.image.width, 1280);
    EXPECT_EQ(view.image.height, 960);
  } catch (const std::exception& error) {
    ADD_FAILURE() << error.what() << "\n" << testing::ReadFile(dir / "up.log");
  }
  up.Signal(SIGTERM);
  const auto status = up.WaitFor(milliseconds(15000));
  ASSERT_TRUE(status.has_value()) << "avc up did not stop on SIGTERM";
  EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 0)
      << launch::DescribeWaitStatus(*status) << "\n"
      << testing::ReadFile(dir / "up.log");
  EXPECT_FALSE(fs::exists(dir / "sim" / "lt360")) << "the pty link is removed on stop";
}

}  // namespace
}  // namespace avc::bench
