// avc-planner's plan jobs, on files as the stage server hands them over: a scan driven one view
// per job through PlanStageHandler ends with exactly the plan of Algorithm 1 run in one call;
// a planner restarted mid-scan (a new handler) replays the answered views and asks for the same
// next view; a request from another plan, bad settings and bad files fail naming the problem.

#include "services/planner/plan_step.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "core/calibration/cell/calibration_yaml.h"
#include "core/plan/plan_exchange.h"
#include "core/util/file_io.h"
#include "services/planner/active_vision.h"
#include "services/planner/calibrated_cell.h"
#include "services/planner/plan_session.h"
#include "services/planner/plan_settings.h"
#include "sim/cell/cell_fixtures.h"
#include "sim/dataset/render_dataset.h"
#include "sim/render/renderer.h"
#include "tests/services/planner/label_mask.h"
#include "tests/support/test_support.h"

namespace avc::planner {
namespace {

namespace fs = std::filesystem;

struct StrapPlant {
  sim::Scene scene;
  cell::CellModel truth;
  StrapPlant() {
    sim::RenderDatasetOptions options;
    options.preset = sim::PlantPreset::kStrap;
    options.plant.target_triangles = 4000;
    scene = sim::MakeScene(options);
    truth = sim::MakeCell(options);
  }
};

class PlanStep : public ::testing::Test {
 protected:
  void SetUp() override {
    calibration::CellCalibration calibration;
    calibration.intrinsics = plant_.truth.intrinsics;
    calibration.T_flange_cam = plant_.truth.T_flange_cam;
    calibration.T_base_table = plant_.truth.T_base_table;
    calibration.dh = plant_.truth.dh;
    calibration::SaveCalibration(calibration, dir_ / "calibration.yaml");
    cell_ = CellModelFromCalibration(calibration::LoadCalibration(dir_ / "calibration.yaml"));
  }

  // One plan job through `handler`, as the stage server runs it: the request and the
  // calibration written into a fresh input folder, the answer read from the output folder.
  plan::PlanAnswer Job(const stage::StageHandler& handler, const plan::PlanRequest& request,
                       const std::vector<std::string>& settings, const std::string& scan_id) {
    const fs::path job = dir_ / ("job-" + std::to_string(jobs_++));
    stage::StageWork work;
    work.input_dir = job / "in";
    work.output_dir = job / "out";
    work.settings = settings;
    work.scan_id = scan_id;
    plan::WritePlanRequest(request, work.input_dir);
    fs::copy_file(dir_ / "calibration.yaml", work.input_dir / kCalibrationFile);
    fs::create_directories(work.output_dir);
    handler(work);
    return plan::ReadPlanAnswer(work.output_dir);
  }

  plan::AnsweredView Answer(const plan::ViewRequest& view) const {
    return {view, plan::EncodeMask(testing::LabelMask(
                      plant_.scene, cell::CameraAt(cell_, view.joints, view.table_angle)))};
  }

  const std::vector<std::string> settings_ = {"levels=2", "views_per_level=6", "max_views=15",
                                              "table_z=-0.2", "table_clearance=0.02"};
  StrapPlant plant_;
  cell::CellModel cell_;
  testing::TempDir dir_{"avc-plan-step"};
  int jobs_ = 0;
};

TEST_F(PlanStep, OneJobPerViewEndsWithTheSamePlanAsOneCall) {
  const PlanSettings settings = ParsePlanSettings(settings_);
  const ActiveVisionResult direct = RunActiveVision(
      cell_,
      [&](const CellView& view) -> std::optional<cv::Mat> {
        return testing::LabelMask(plant_.scene, view.camera);
      },
      settings.planner);
  ASSERT_GE(direct.views.size(), 12u);

  const stage::StageHandler handler = PlanStageHandler();
  plan::PlanRequest request;
  plan::PlanAnswer answer;
  std::vector<plan::PlanPhase> phases;
  for (int job = 0; job < 200; ++job) {
    answer = Job(handler, request, settings_, "scan-a");
    phases.push_back(answer.phase);
    if (answer.final_plan) break;
    request.answered.push_back(Answer(*answer.next));
  }
  ASSERT_TRUE(answer.final_plan.has_value());
  const plan::FinalPlan expected = FinalPlanOf(direct);
  ASSERT_EQ(answer.final_plan->views.size(), expected.views.size());
  for (size_t i = 0; i < expected.views.size(); ++i) {
    EXPECT_TRUE(plan::SameView(answer.final_plan->views[i].view, expected.views[i].view, 0))
        << "view " << i;
    EXPECT_EQ(answer.final_plan->views[i].reason, expected.views[i].reason) << "view " << i;
    EXPECT_EQ(answer.final_plan->views[i].kept, expected.views[i].kept) << "view " << i;
  }
  EXPECT_EQ(answer.final_plan->patches, expected.patches);
  EXPECT_EQ(answer.final_plan->notes, expected.notes);
  EXPECT_TRUE(std::is_sorted(phases.begin(), phases.end())) << "phases only move forward";
  EXPECT_EQ(phases.back(), plan::PlanPhase::kPruneViews);
  EXPECT_FALSE(answer.keep_out.empty()) << "the plant's keep-out goes to the scan";
  EXPECT_EQ(answer.settings.at("max_views"), "15");

  // A planner restarted after 11 answered views (a new handler knows no session) replays them
  // and asks for the same twelfth view as the planner that ran on.
  plan::PlanRequest eleven;
  eleven.answered.assign(request.answered.begin(), request.answered.begin() + 11);
  const plan::PlanAnswer replayed = Job(PlanStageHandler(), eleven, settings_, "scan-a");
  ASSERT_TRUE(replayed.next.has_value());
  EXPECT_TRUE(plan::SameView(*replayed.next, request.answered[11].view, 0));
}

TEST_F(PlanStep, ARequestFromAnotherPlanFailsNamingTheView) {
  const stage::StageHandler handler = PlanStageHandler();
  const plan::PlanAnswer first = Job(handler, {}, settings_, "scan-b");
  ASSERT_TRUE(first.next.has_value());
  plan::PlanRequest request;
  request.answered.push_back(Answer(*first.next));
  request.answered[0].view.table_angle += 0.3;  // not the view the planner asked for
  try {
    Job(handler, request, settings_, "scan-b");
    ADD_FAILURE() << "a request from another plan must fail";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("view 0 is not the view the planner asks for"),
              std::string::npos)
        << error.what();
  }
}

TEST_F(PlanStep, BadSettingsAndFilesAreNamed) {
  const auto error_of = [&](const std::vector<std::string>& settings) -> std::string {
    try {
      ParsePlanSettings(settings);
    } catch (const std::invalid_argument& error) {
      return error.what();
    }
    return "";
  };
  EXPECT_NE(error_of({"max_view=4"}).find("max_view=4: no such option"), std::string::npos);
  EXPECT_NE(error_of({"levels=two"}).find("levels=two: 'two' is not an integer"),
            std::string::npos);
  EXPECT_NE(error_of({"prune_face_loss=1.5"}).find("1.5 is above the maximum 1"),
            std::string::npos);
  EXPECT_NE(error_of({"keep_out=1 2 3"}).find("is not five numbers"), std::string::npos);
  EXPECT_NE(error_of({"levels"}).find("expected SECTION.FIELD=VALUE"), std::string::npos);
  EXPECT_NE(error_of({"keep_out=0 0 -1 0 1"}).find("safety envelope is not usable"),
            std::string::npos);
  const PlanSettings parsed = ParsePlanSettings({"keep_out=0.1 0 0.2 -0.5 0.1", "table_z=-0.3"});
  ASSERT_TRUE(parsed.planner.reach.envelope.has_value());
  EXPECT_TRUE(parsed.planner.reach.envelope->keep_out.has_value());
  EXPECT_EQ(ParsePlanSettings({"max_views=9", "prune_face_loss=0.01", "keep_out_margin=0.03"})
                .planner.max_views,
            9);
  const std::map<std::string, std::string> described =
      DescribePlanSettings(ParsePlanSettings({"prune_face_loss=0.01", "keep_out_margin=0.03"}));
  EXPECT_EQ(described.at("prune_face_loss"), "0.01");
  EXPECT_EQ(described.at("keep_out_margin"), "0.03");

  // A damaged request names its file and field.
  const fs::path folder = dir_ / "damaged";
  fs::create_directories(folder);
  WriteFileAtomically(folder / plan::kRequestFile,
                      R"({"answered": [{"joints": [0, 0, 0], "table_angle": 0, "mask": null}]})");
  try {
    plan::ReadPlanRequest(folder);
    ADD_FAILURE() << "three joints are not a view";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("answered[0].joints must be 6 numbers"),
              std::string::npos)
        << error.what();
  }
  EXPECT_THROW(plan::DecodeMask("not a png", "the mask of view 3"), std::runtime_error);
}

}  // namespace
}  // namespace avc::planner
