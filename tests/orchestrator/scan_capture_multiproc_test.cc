// The scan's capture step as the orchestrator runs it: the planner's views taken through the
// simulated cell and every real driver (separate processes on the real bus), each image kept in
// the scan directory and scan.json. A restarted orchestrator (new client, record read back from
// disk) gets the views it already has from their files with no capture, recaptures only a
// deleted one, refuses a plan that contradicts the record, skips a view the arm refuses
// (outside its limits or inside the plant's keep-out) and waits for a camera driver that was
// killed and restarted.

#include <gtest/gtest.h>

#include <filesystem>
#include <numbers>
#include <opencv2/core.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/devices/cell_processes.h"
#include "core/bus/bus.h"
#include "core/bus/bus_options.h"
#include "drivers/client/cell_client.h"
#include "orchestrator/scan_capture.h"
#include "orchestrator/scan_record.h"
#include "services/planner/cell_view.h"
#include "sim/cell/view_selection.h"
#include "sim/dataset/render_dataset.h"
#include "sim/emulators/cell/simulated_cell.h"
#include "tests/support/test_support.h"

namespace avc::orchestrator {
namespace {

namespace fs = std::filesystem;
using std::chrono::milliseconds;

constexpr int kCaptureWidth = 320, kCaptureHeight = 240;

// Views around the plant at one height, as the planner realises them in the nominal cell.
std::vector<plan::ViewRequest> ViewsAround(const sim::CellTruth& model, int count) {
  std::vector<plan::ViewRequest> views;
  const Eigen::Vector3d target(0, 0, 0.08);
  kinematics::JointVector joints = sim::StartJoints(model);
  for (int n = 0; n < count; ++n) {
    const double azimuth = sim::RobotAzimuth(model) + n * 2 * std::numbers::pi / count;
    const Eigen::Vector3d eye =
        sim::ViewpointOnSphere(target, 0.55, 30 * std::numbers::pi / 180, azimuth);
    const auto view = planner::RealiseView(model, eye, target, {}, joints);
    if (!view) throw std::runtime_error("test view unreachable");
    joints = view->joints;
    views.push_back({view->joints, view->turntable_angle});
  }
  return views;
}

size_t PlantPixels(const std::optional<cv::Mat>& mask) {
  return mask ? static_cast<size_t>(cv::countNonZero(*mask)) : 0;
}

TEST(ScanCaptureMultiproc, KeepsEveryImageAndResumesWithoutCapturingAgain) {
  testing::TempDir dir("avc-scan-capture");
  const fs::path scan_dir = dir.path() / "scan";
  fs::create_directories(scan_dir);
  const bus::BusOptions bus_options = bus::ResolveBusOptions({}, "scan-capture-test");
  bench::CellProcessOptions options =
      bench::CellOptionsOnBus(bus_options, testing::Executable("avc"), dir.path());
  options.time_scale = 10;
  options.triangles = 6000;
  options.width = kCaptureWidth;
  options.height = kCaptureHeight;
  options.png = true;
  options.stages = false;  // captures only
  bench::CellProcesses cell(options);

  sim::RenderDatasetOptions model_options;
  model_options.width = kCaptureWidth;
  model_options.height = kCaptureHeight;
  const sim::CellTruth model = sim::MakeCell(model_options);
  const std::vector<plan::ViewRequest> views = ViewsAround(model, 4);

  bus::Bus bus(bus_options);
  bus::EventLoop loop;
  bus.AttachTo(loop);
  try {
    std::vector<cv::Mat> first_masks;
    {
      client::CellClient client(bus, loop, "avc-orchestrator", cell.key());
      client.WaitReady({"avc-sim", "avc-robot", "avc-turntable", "avc-camera"},
                       milliseconds(20000));
      client.Robot(avc::robot_command_t::KIND_POWER_ON, milliseconds(10000));
      client.Robot(avc::robot_command_t::KIND_BRAKE_RELEASE, milliseconds(10000));

      ScanRecord record;
      record.scan_id = "capture-test";
      int saves = 0;
      std::vector<std::string> progress;
      ScanCapture capture(
          client, scan_dir, record,
          [&] {
            SaveScanRecord(record, scan_dir);
            ++saves;
          },
          {}, [&](const std::string& line) { progress.push_back(line); });
      for (int n = 0; n < 3; ++n) {
        // A crashed camera driver, restarted as `avc up` would: it refuses captures until it has
        // its camera again, which must delay the view, never skip it (a skipped view left a gap
        // in the image ids and changed the plan).
        if (n == 2) cell.KillAndRestart("avc-camera");
        const std::optional<cv::Mat> mask = capture(views[n]);
        ASSERT_TRUE(mask.has_value());
        EXPECT_EQ(mask->cols, kCaptureWidth);
        EXPECT_GT(PlantPixels(mask), 0.01 * kCaptureWidth * kCaptureHeight) << "view " << n;
        first_masks.push_back(*mask);
      }
      EXPECT_EQ(capture.taken(), 3);
      EXPECT_EQ(saves, 3);

      // A joint target outside the arm's limits is refused by the driver: skipped, not fatal.
      plan::ViewRequest impossible = views[3];
      impossible.joints[1] = 7.0;
      EXPECT_FALSE(capture(impossible).has_value());
      EXPECT_EQ(record.captures.size(), 3u);

      // A plant keep-out the arm cannot stay out of (60 cm about the turntable axis at every
      // height): the next view is refused by the driver and skipped too. The ScanCapture of the
      // restarted orchestrator below starts with none and clears it in the driver.
      kinematics::PlantKeepOut plant;
      plant.T_base_table = model.T_base_table;
      plant.z0_m = -0.6;
      plant.radius_m.assign(60, 0.6);
      capture.SetPlantKeepOut(plant);
      EXPECT_FALSE(capture(views[3]).has_value());
      EXPECT_EQ(record.captures.size(), 3u);
      ASSERT_FALSE(progress.empty());
      EXPECT_NE(progress.back().find("plant's keep-out"), std::string::npos) << progress.back();
    }
    EXPECT_EQ(sim::ReadTruthLog(cell.truth_log()).size(), 3u);

    // What a restarted orchestrator finds on disk.
    ScanRecord record = LoadScanRecord(scan_dir);
    ASSERT_EQ(record.captures.size(), 3u);
    for (const CaptureRecord& c : record.captures) {
      EXPECT_TRUE(fs::exists(scan_dir / c.file)) << c.file;
      EXPECT_EQ(c.sha256.size(), 64u);
    }
    EXPECT_EQ(record.captures[1].image_id, "view_0001");
    EXPECT_EQ(record.captures[2].image_id, "view_0002") << "the camera's restart cost no view";
    fs::remove(scan_dir / record.captures[1].file);

    client::CellClient client(bus, loop, "avc-orchestrator", cell.key());
    client.WaitReady({"avc-robot", "avc-turntable", "avc-camera"}, milliseconds(20000));
    ScanCapture resumed(client, scan_dir, record, [&] { SaveScanRecord(record, scan_dir); });
    const std::optional<cv::Mat> again = resumed(views[0]);
    ASSERT_TRUE(again.has_value());
    EXPECT_EQ(cv::norm(*again, first_masks[0], cv::NORM_INF), 0) << "same file, same mask";
    EXPECT_GT(PlantPixels(resumed(views[1])), 0u);  // deleted: captured again
    EXPECT_GT(PlantPixels(resumed(views[2])), 0u);
    EXPECT_GT(PlantPixels(resumed(views[3])), 0u);  // new
    EXPECT_EQ(resumed.reused(), 2);
    EXPECT_EQ(resumed.taken(), 2);
    EXPECT_EQ(sim::ReadTruthLog(cell.truth_log()).size(), 5u) << "only two more captures";
    const ScanRecord final_record = LoadScanRecord(scan_dir);
    ASSERT_EQ(final_record.captures.size(), 4u);
    EXPECT_TRUE(VerifyCaptures(final_record, scan_dir).empty());

    // A plan that no longer matches the record stops the scan instead of mixing two plans.
    ScanCapture contradicted(client, scan_dir, record, [] {});
    EXPECT_THROW(
        {
          try {
            contradicted(views[2]);
          } catch (const std::runtime_error& error) {
            EXPECT_NE(std::string(error.what()).find("cannot be resumed"), std::string::npos)
                << error.what();
            throw;
          }
        },
        std::runtime_error);

    // A calibration of another camera (640x480 where the cell's camera gives 320x240): the first
    // capture stops the scan saying what to do, and nothing is added to the record or the disk.
    sim::RenderDatasetOptions other_options = model_options;
    other_options.width = 2 * kCaptureWidth;
    other_options.height = 2 * kCaptureHeight;
    const plan::ViewRequest other_camera = ViewsAround(sim::MakeCell(other_options), 4)[0];
    ScanRecord fresh;
    const fs::path other_dir = dir.path() / "other-camera";
    ScanCaptureOptions other_calibration;
    other_calibration.image_width = other_options.width;
    other_calibration.image_height = other_options.height;
    ScanCapture mismatched(
        client, other_dir, fresh, [] {}, other_calibration);
    try {
      mismatched(other_camera);
      ADD_FAILURE() << "a calibration of another camera must stop the scan";
    } catch (const std::runtime_error& error) {
      const std::string what = error.what();
      EXPECT_NE(what.find("delivered 320x240 but the calibration's camera is 640x480"),
                std::string::npos)
          << what;
      EXPECT_NE(what.find("load the calibration of this camera"), std::string::npos) << what;
    }
    EXPECT_TRUE(fresh.captures.empty());
    EXPECT_FALSE(fs::exists(other_dir / "images"));
  } catch (const std::exception& error) {
    FAIL() << error.what() << "\n" << cell.LogTails();
  }
  EXPECT_TRUE(cell.Exited().empty()) << cell.LogTails();
}

}  // namespace
}  // namespace avc::orchestrator
