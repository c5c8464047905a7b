// A resumed scan takes the planner settings its scan.json recorded (also the counts an older
// scan kept), refuses damaged ones by name, and names what a resume's command line would change.

#include "orchestrator/scan_planner_settings.h"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <string>

#include "core/plan/plan_settings.h"

namespace avc::orchestrator {
namespace {

std::string RecordedError(const nlohmann::json& options) {
  try {
    RecordedPlannerSettings(options);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

TEST(ScanPlannerSettings, RecordedSettingsComeBackAsTheyWere) {
  const PlannerSettings started = {{"max_views", "50"},
                                   {"levels", "4"},
                                   {"prune_face_loss", "0.01"},
                                   {"keep_out", "0.1 0 0.2 -0.5 0.1"}};
  nlohmann::json options = {{"calibration_file", "/data/cal.yaml"}};
  RecordPlannerSettings(started, &options);
  EXPECT_EQ(options.at("calibration_file"), "/data/cal.yaml") << "other keys are kept";
  EXPECT_EQ(RecordedPlannerSettings(nlohmann::json::parse(options.dump())), started);
  EXPECT_EQ(PlannerAssignments(started),
            (std::vector<std::string>{"keep_out=0.1 0 0.2 -0.5 0.1", "levels=4", "max_views=50",
                                      "prune_face_loss=0.01"}));
}

TEST(ScanPlannerSettings, AnOlderScansCountsAreRead) {
  EXPECT_EQ(RecordedPlannerSettings(
                {{"max_views", 40}, {"levels", 3}, {"prune_face_loss", 0.25}, {"other", "x"}}),
            (PlannerSettings{{"max_views", "40"}, {"levels", "3"}, {"prune_face_loss", "0.25"}}));
  EXPECT_TRUE(RecordedPlannerSettings({{"calibration_file", "a.yaml"}}).empty());
}

TEST(ScanPlannerSettings, DamagedValuesAreRefusedNamingTheKey) {
  EXPECT_NE(RecordedError({{"planner_settings", {{"max_views", 40}}}})
                .find("options.planner_settings.max_views must be a string"),
            std::string::npos);
  EXPECT_NE(RecordedError({{"planner_settings", "max_views=40"}})
                .find("options.planner_settings must be an object"),
            std::string::npos);
  EXPECT_NE(RecordedError({{"max_views", "forty"}}).find("options.max_views must be a number"),
            std::string::npos);
  EXPECT_NE(RecordedError(nlohmann::json::array()).find("options must be an object"),
            std::string::npos);
  EXPECT_EQ(RecordedError({{"max_views", 40}, {"planner_notes", {"x"}}}), "");
}

TEST(ScanPlannerSettings, ChangesAreNamedWithBothValues) {
  const PlannerSettings recorded = {{"max_views", "14"}, {"prune_face_loss", "1"}};
  PlannerSettings given = recorded;
  const std::set<std::string> all = {plan::kMaxViews, plan::kLevels, plan::kViewsPerLevel,
                                     plan::kPruneFaceLoss};
  EXPECT_EQ(DescribePlannerChanges(recorded, given, all), "")
      << "the same settings plan the same views";
  given["max_views"] = "50";
  given["prune_face_loss"] = "0.01";
  given["levels"] = "4";  // not recorded: no change
  EXPECT_EQ(DescribePlannerChanges(recorded, given, all),
            "max_views 14 (given 50), prune_face_loss 1 (given 0.01)");
  // A setting the caller did not choose (a default of the command line) is not a change.
  EXPECT_EQ(DescribePlannerChanges(recorded, given, {plan::kPruneFaceLoss}),
            "prune_face_loss 1 (given 0.01)");
}

}  // namespace
}  // namespace avc::orchestrator
