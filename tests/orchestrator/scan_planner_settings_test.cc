// A resumed scan takes the planner settings its scan.json recorded, refuses damaged ones by name,
// and names what a resume's command line would change.

#include "orchestrator/scan_planner_settings.h"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <string>

namespace avc::orchestrator {
namespace {

std::string RestoreError(const nlohmann::json& options) {
  planner::ActiveVisionOptions planner;
  try {
    RestorePlannerSettings(options, &planner);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

TEST(ScanPlannerSettings, RecordedSettingsComeBackOverOtherValues) {
  planner::ActiveVisionOptions started;
  started.max_views = 50;
  started.levels = 4;
  started.views_per_level = 12;
  started.prune_max_covered_faces_lost = 0.01;
  nlohmann::json options = {{"calibration_file", "/data/cal.yaml"}};
  RecordPlannerSettings(started, &options);
  EXPECT_EQ(options.at("calibration_file"), "/data/cal.yaml") << "other keys are kept";

  planner::ActiveVisionOptions resumed;  // the defaults a resume without flags would bring
  RestorePlannerSettings(nlohmann::json::parse(options.dump()), &resumed);
  EXPECT_EQ(resumed.max_views, 50);
  EXPECT_EQ(resumed.levels, 4);
  EXPECT_EQ(resumed.views_per_level, 12);
  EXPECT_DOUBLE_EQ(resumed.prune_max_covered_faces_lost, 0.01);
}

TEST(ScanPlannerSettings, AnOlderScanWithoutTheFaceLimitKeepsThePapersRule) {
  planner::ActiveVisionOptions resumed;
  resumed.prune_max_covered_faces_lost = 0.3;
  RestorePlannerSettings({{"max_views", 40}, {"levels", 3}, {"views_per_level", 10}}, &resumed);
  EXPECT_EQ(resumed.max_views, 40);
  EXPECT_DOUBLE_EQ(resumed.prune_max_covered_faces_lost, 0.3) << "absent keys are left alone";
}

TEST(ScanPlannerSettings, DamagedValuesAreRefusedNamingTheKey) {
  EXPECT_NE(RestoreError({{"max_views", "forty"}}).find("options.max_views must be an integer"),
            std::string::npos);
  EXPECT_NE(RestoreError({{"views_per_level", 0}}).find("options.views_per_level must be in"),
            std::string::npos);
  EXPECT_NE(RestoreError({{"levels", 2.5}}).find("options.levels"), std::string::npos);
  EXPECT_NE(RestoreError({{"prune_face_loss", 1.5}}).find("options.prune_face_loss must be in"),
            std::string::npos);
  EXPECT_NE(RestoreError({{"prune_face_loss", nullptr}}).find("must be a number"),
            std::string::npos);
  EXPECT_NE(RestoreError(nlohmann::json::array()).find("options must be an object"),
            std::string::npos);
  EXPECT_EQ(RestoreError({{"max_views", 40}, {"planner_notes", {"x"}}}), "");
}

TEST(ScanPlannerSettings, ChangesAreNamedWithBothValues) {
  planner::ActiveVisionOptions recorded;
  recorded.max_views = 14;
  planner::ActiveVisionOptions given = recorded;
  const std::set<std::string> all = {kMaxViewsSetting, kLevelsSetting, kViewsPerLevelSetting,
                                     kPruneFaceLossSetting};
  EXPECT_EQ(DescribePlannerChanges(recorded, given, all), "")
      << "the same settings plan the same views";
  given.max_views = 50;
  given.prune_max_covered_faces_lost = 0.01;
  EXPECT_EQ(DescribePlannerChanges(recorded, given, all),
            "max_views 14 (given 50), prune_face_loss 1 (given 0.01)");
  // A setting the caller did not choose (a default of the command line) is not a change.
  EXPECT_EQ(DescribePlannerChanges(recorded, given, {kPruneFaceLossSetting}),
            "prune_face_loss 1 (given 0.01)");
  EXPECT_EQ(DescribePlannerChanges(recorded, given, {}), "");
}

}  // namespace
}  // namespace avc::orchestrator
