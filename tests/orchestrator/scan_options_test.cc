// avc scan's options: Algorithm 1's settings are checked against the ranges the planner declares
// and sent only when given, the safety envelope joins the plan settings only when there is one
// and is refused when the driver could not enforce it, and a scan's configuration reads back to
// itself.

#include "orchestrator/scan_options.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/config/option_text.h"
#include "core/plan/plan_settings.h"
#include "services/planner/plan_settings.h"

namespace avc::orchestrator {
namespace {

ScanOptions Apply(const std::vector<std::string>& sets, ScanOptions options = {}) {
  ScanOptionTable().ApplyTexts(options, sets, "--set");
  return options;
}

std::string Refusal(const std::vector<std::string>& sets) {
  try {
    Apply(sets);
  } catch (const config::ConfigError& error) {
    return error.what();
  }
  return "";
}

TEST(ScanOptions, DefaultsSendThePlannerNothing) {
  const ScanRunOptions run = ScanOptions{}.RunOptions();
  EXPECT_TRUE(run.planner_settings.empty());
  EXPECT_TRUE(run.planner_settings_given.empty());
  EXPECT_EQ(run.ready_timeout, std::chrono::seconds(30));
  EXPECT_EQ(run.capture.encoding, avc::image_t::ENCODING_PNG);
}

TEST(ScanOptions, GivenPlannerSettingsAreSentAndMayNotChangeOnResume) {
  const ScanOptions options =
      Apply({"planner.max_views=50", "planner.prune_face_loss=0.01", "planner.levels=4"});
  const ScanRunOptions run = options.RunOptions();
  EXPECT_EQ(run.planner_settings,
            (PlannerSettings{{"max_views", "50"}, {"prune_face_loss", "0.01"}, {"levels", "4"}}));
  EXPECT_EQ(run.planner_settings_given,
            (std::set<std::string>{"max_views", "prune_face_loss", "levels"}));
  // "none" takes a setting back: the planner's own default again.
  const ScanRunOptions back = Apply({"planner.max_views=none"}, options).RunOptions();
  EXPECT_FALSE(back.planner_settings.contains("max_views"));
  EXPECT_FALSE(back.planner_settings_given.contains("max_views"));
}

TEST(ScanOptions, PlannerSettingsAreCheckedAsThePlannerChecksThem) {
  for (const plan::AlgorithmSetting& setting : plan::AlgorithmSettings()) {
    const std::string above = std::to_string(static_cast<long long>(setting.spec.max) + 1);
    const std::string message = Refusal({fmt::format("planner.{}={}", setting.name, above)});
    EXPECT_NE(message.find(std::string("planner.") + setting.name), std::string::npos) << message;
    EXPECT_NE(message.find("--set"), std::string::npos) << message;
    // avc-planner refuses the same value for a job.
    EXPECT_THROW(planner::ParsePlanSettings({fmt::format("{}={}", setting.name, above)}),
                 config::ConfigError)
        << setting.name;
  }
  EXPECT_NE(Refusal({"planner.max_views=12.5"}).find("not an integer"), std::string::npos);
  EXPECT_NE(Refusal({"planner.max_view=12"}).find("no such option"), std::string::npos);
}

TEST(ScanOptions, TheEnvelopeJoinsThePlanSettingsOnlyWhenThereIsOne) {
  EXPECT_TRUE(Apply({"envelope.table_clearance=0.05"}).RunOptions().planner_settings.empty());
  const ScanRunOptions run =
      Apply({"envelope.table_z=-0.26", "envelope.keep_out=0.5 0 0.3 -0.3 0.1"}).RunOptions();
  EXPECT_EQ(run.planner_settings.at(plan::kTableZ), "-0.26");
  EXPECT_EQ(run.planner_settings.at(plan::kKeepOut), "0.5 0 0.3 -0.3 0.1");
  EXPECT_TRUE(run.planner_settings.contains(plan::kTableClearance));
  EXPECT_TRUE(run.planner_settings_given.empty()) << "the cell's envelope is not the plan's";
  EXPECT_NE(Refusal({"envelope.keep_out=1 2 3"}).find("envelope.keep_out"), std::string::npos);
  // A cylinder whose bottom is above its top: the driver could not enforce it.
  EXPECT_NE(Refusal({"envelope.keep_out=0 0 0.2 0.5 0.1"}).find("safety envelope"),
            std::string::npos);
}

TEST(ScanOptions, CaptureAndTimeouts) {
  const ScanRunOptions run = Apply({"capture.encoding=jpeg", "scan.ready_timeout=1000",
                                    "capture.masks.method=excess_green"})
                                 .RunOptions();
  EXPECT_EQ(run.capture.encoding, avc::image_t::ENCODING_JPEG);
  EXPECT_EQ(run.ready_timeout, std::chrono::seconds(1));
  EXPECT_EQ(run.capture.mask.method, segmentation::MaskMethod::kExcessGreen);
  EXPECT_NE(Refusal({"capture.encoding=gif"}).find("not png or jpeg"), std::string::npos);
  EXPECT_NE(Refusal({"scan.stage_timeout=0"}).find("scan.stage_timeout"), std::string::npos);
}

TEST(ScanOptions, AScansConfigurationReadsBackToItself) {
  const ScanOptions options = Apply({"planner.max_views=20", "envelope.table_z=-0.1",
                                     "capture.encoding=jpeg", "capture.pose_tolerance=0.001"});
  const std::string text = ScanOptionTable().ToToml(options);
  const auto file = std::filesystem::path(::testing::TempDir()) / "avc-scan.toml";
  std::ofstream(file) << text;
  const ScanOptions read = ScanOptionTable().Load(ScanOptions{}, {file.string()}, {});
  EXPECT_EQ(ScanOptionTable().ToToml(read), text);
  EXPECT_EQ(read.RunOptions().planner_settings, options.RunOptions().planner_settings);
  EXPECT_NE(text.find("[planner]\nmax_views = '20'"), std::string::npos) << text;
}

}  // namespace
}  // namespace avc::orchestrator
