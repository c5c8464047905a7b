// Algorithm 1 end to end in the simulated cell, without the bus: captures are rendered label
// images (a perfect colour filter) at a quarter of the camera's size. The run frames the plant,
// takes the 3x10 orbit, adds views for badly seen patches with their reasons, removes redundant
// ones without losing ground-truth coverage, and is deterministic; every move it makes passes the
// arm driver's envelope (bench and turntable) from where the arm was; a plant the colour filter
// cannot find, or captures that fail, are reported rather than crashing.

#include "services/planner/active_vision.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <opencv2/imgproc.hpp>

#include "core/eval/coverage.h"
#include "core/geometry/mesh.h"
#include "sim/cell/cell_fixtures.h"
#include "sim/cell/view_selection.h"
#include "sim/dataset/render_dataset.h"
#include "sim/render/renderer.h"
#include "tests/services/planner/label_mask.h"

namespace avc::planner {
namespace {

struct Plant {
  sim::Scene scene;
  sim::CellTruth cell;
  Plant() {
    sim::RenderDatasetOptions options;
    options.preset = sim::PlantPreset::kBroadleaf;
    scene = sim::MakeScene(options);
    cell = sim::MakeCell(options);
  }
};

const Plant& TestPlant() {
  static const Plant plant;
  return plant;
}

ActiveVisionOptions SmallRun() {
  ActiveVisionOptions options;
  options.max_views = 34;
  options.reach.envelope = kinematics::PlanningEnvelope(sim::FixturesEnvelope(TestPlant().cell));
  return options;
}

TEST(ActiveVision, FramesOrbitsAddsViewsAndPrunesWithoutLosingCoverage) {
  const Plant& plant = TestPlant();
  // Each stage is announced once, in order, and the orbit starts only after framing captured.
  std::vector<ActiveVisionStage> stages;
  std::vector<size_t> captures_at_stage;
  size_t captures = 0;
  // Each move, framing frames included, as avc-robot would check it (without the planner's
  // margin): from the joints of the capture before.
  const kinematics::SafetyEnvelope driver = sim::FixturesEnvelope(plant.cell);
  kinematics::JointVector arm = sim::StartJoints(plant.cell);
  std::vector<std::string> refusals;
  const auto capture = [&](const CellView& view) {
    ++captures;
    const std::string refusal =
        kinematics::CheckJointMove(driver, plant.cell.dh, arm, view.joints, 1.0, 1.0);
    if (!refusal.empty()) refusals.push_back(refusal);
    arm = view.joints;
    return std::optional(testing::LabelMask(plant.scene, view.camera));
  };
  // The proxy is announced when it is made from the first height and after each view after.
  std::vector<int> proxy_views;
  const ActiveVisionResult result = RunActiveVision(
      plant.cell, capture, SmallRun(),
      [&](ActiveVisionStage stage) {
        stages.push_back(stage);
        captures_at_stage.push_back(captures);
      },
      [&](const ppr::PlantProxy& proxy) { proxy_views.push_back(proxy.view_count()); });
  EXPECT_TRUE(refusals.empty()) << refusals.size() << " moves refused, the first: "
                                << (refusals.empty() ? "" : refusals.front());
  ASSERT_FALSE(proxy_views.empty());
  EXPECT_EQ(proxy_views.front(), 10);
  EXPECT_EQ(proxy_views.size(), result.views.size() - 10 + 1);
  for (size_t i = 1; i < proxy_views.size(); ++i) EXPECT_EQ(proxy_views[i], proxy_views[i - 1] + 1);
  EXPECT_EQ(stages, (std::vector<ActiveVisionStage>{
                        ActiveVisionStage::kFrame, ActiveVisionStage::kInitialCapture,
                        ActiveVisionStage::kActiveVision, ActiveVisionStage::kPruneViews}));
  ASSERT_EQ(captures_at_stage.size(), 4u);
  EXPECT_EQ(captures_at_stage[0], 0u);
  EXPECT_GT(captures_at_stage[1], captures_at_stage[0]) << "framing takes frames first";
  EXPECT_GE(captures_at_stage[2], captures_at_stage[1] + 30) << "the whole orbit before NBV";

  const size_t initial = std::count_if(result.views.begin(), result.views.end(),
                                       [](const PlannedView& v) { return v.phase == "initial"; });
  EXPECT_EQ(initial, 30u);
  EXPECT_LE(result.views.size(), 34u);
  EXPECT_GT(result.views.size(), initial) << "no active view was needed or found";
  EXPECT_LE(result.KeptCount(), result.views.size());
  for (const PlannedView& v : result.views) {
    if (v.phase != "active") continue;
    EXPECT_GE(v.patch, 0);
    EXPECT_NE(v.reason.find("patch"), std::string::npos) << v.reason;
    EXPECT_LT(v.patch_score, 1.0);
  }
  ASSERT_TRUE(result.proxy.has_value());
  EXPECT_GT(result.proxy->Counts().occupied, 1000u);
  ASSERT_EQ(result.framed_distances.size(), 3u);
  for (const double d : result.framed_distances) {
    EXPECT_GT(d, 0.2);
    EXPECT_LT(d, 1.2);
  }

  // Ground truth: the kept views cover at least what the orbit alone does.
  geometry::Mesh organs;
  organs.vertices = plant.scene.mesh.vertices;
  for (size_t f = 0; f < plant.scene.mesh.faces.size(); ++f) {
    if (plant.scene.mesh.face_labels[f] >= geometry::labels::kStem) {
      organs.faces.push_back(plant.scene.mesh.faces[f]);
    }
  }
  const eval::CoverageModel model(organs, 1e5, 1);
  std::vector<camera::Camera> kept, orbit;
  for (const PlannedView& v : result.views) {
    if (v.kept) kept.push_back(v.view.camera);
    if (v.phase == "initial") orbit.push_back(v.view.camera);
  }
  const double kept_coverage = model.Evaluate(kept).fraction;
  const double orbit_coverage = model.Evaluate(orbit).fraction;
  EXPECT_GT(orbit_coverage, 0.9);
  EXPECT_GE(kept_coverage, orbit_coverage - 0.005)
      << "kept " << kept.size() << " views: " << kept_coverage << ", orbit " << orbit_coverage;

  // Same plant and captures, same plan.
  arm = sim::StartJoints(plant.cell);
  const ActiveVisionResult again = RunActiveVision(plant.cell, capture, SmallRun());
  ASSERT_EQ(again.views.size(), result.views.size());
  for (size_t i = 0; i < result.views.size(); ++i) {
    EXPECT_EQ(again.views[i].view.turntable_angle, result.views[i].view.turntable_angle) << i;
    EXPECT_EQ(again.views[i].view.joints, result.views[i].view.joints) << i;
    EXPECT_EQ(again.views[i].kept, result.views[i].kept) << i;
  }
}

TEST(ActiveVision, NoPlantAndFailedCapturesAreReported) {
  const Plant& plant = TestPlant();
  const auto nothing = [](const CellView& view) {
    return std::optional<cv::Mat>(
        cv::Mat::zeros(view.camera.intrinsics.height, view.camera.intrinsics.width, CV_8UC1));
  };
  try {
    RunActiveVision(plant.cell, nothing, SmallRun());
    ADD_FAILURE() << "an empty scene must stop the run";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("no plant found"), std::string::npos) << error.what();
  }

  // Every fifth capture fails: those views are skipped and named, the run completes.
  int calls = 0;
  const auto flaky = [&](const CellView& view) -> std::optional<cv::Mat> {
    if (++calls % 5 == 0) return std::nullopt;
    return std::optional(testing::LabelMask(plant.scene, view.camera));
  };
  ActiveVisionOptions options = SmallRun();
  options.max_views = 30;
  const ActiveVisionResult result = RunActiveVision(plant.cell, flaky, options);
  const size_t initial = std::count_if(result.views.begin(), result.views.end(),
                                       [](const PlannedView& v) { return v.phase == "initial"; });
  EXPECT_LT(initial, 30u);              // the failed ones are missing ...
  EXPECT_LE(result.views.size(), 30u);  // ... and the budget still holds
  EXPECT_TRUE(std::any_of(result.notes.begin(), result.notes.end(), [](const std::string& n) {
    return n.find("capture failed") != std::string::npos;
  }));
}

}  // namespace
}  // namespace avc::planner
