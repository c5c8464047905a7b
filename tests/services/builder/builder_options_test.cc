// avc-builder's options table: the names `avc reconstruct --set`, `avc builder --config` and a
// build job's settings use.

#include "services/builder/builder_options.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace avc::builder {
namespace {

std::string ErrorOf(const std::string& assignment) {
  ReconstructOptions options;
  try {
    BuilderOptionTable().ApplyTexts(options, {assignment}, "--set");
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(BuilderOptions, SetsFieldsOfEachSection) {
  ReconstructOptions options;
  BuilderOptionTable().ApplyTexts(
      options,
      {"patch.window=7", "patch.ncc_threshold=0.8", "sweep.best_k=3",
       "proxy.background_votes_allowed=2", "soil.min_elevation_deg=40", "method=plane-sweep",
       "masks.method=excess_green", "soil.enabled=false"},
      "--set");
  EXPECT_DOUBLE_EQ(options.soil.min_elevation_deg, 40.0);
  EXPECT_EQ(options.patch.window, 7);
  EXPECT_DOUBLE_EQ(options.patch.ncc_threshold, 0.8);
  EXPECT_EQ(options.sweep.best_k, 3);
  EXPECT_EQ(options.proxy.background_votes_allowed, 2);
  EXPECT_EQ(options.method, MvsMethod::kPlaneSweep);
  EXPECT_EQ(options.masks.method, segmentation::MaskMethod::kExcessGreen);
  EXPECT_FALSE(options.soil.enabled);
}

TEST(BuilderOptions, RefusesUnknownNamesBadNumbersAndInvalidValuesUnchanged) {
  EXPECT_NE(ErrorOf("patch.windw=7").find("patch.windw=7: no such option"), std::string::npos);
  EXPECT_NE(ErrorOf("patch.window").find("expected SECTION.FIELD=VALUE"), std::string::npos);
  EXPECT_NE(ErrorOf("patch.window=7.5").find("not an integer"), std::string::npos);
  EXPECT_NE(ErrorOf("patch.window=6").find("PatchMvsOptions.window"), std::string::npos);
  EXPECT_NE(ErrorOf("method=fast").find("method=fast"), std::string::npos);
  EXPECT_NE(ErrorOf("soil.outer_radius=0.01").find("SoilLevelOptions.outer_radius"),
            std::string::npos);
  ReconstructOptions options;
  EXPECT_THROW(BuilderOptionTable().ApplyTexts(options, {"patch.window=6"}, "--set"),
               config::ConfigError);
  EXPECT_EQ(options.patch.window, ReconstructOptions{}.patch.window);
}

// The configuration the builder publishes reads back to the options it runs with, so a replay
// given that text builds with the same options.
TEST(BuilderOptions, ConfigurationInForceReadsBackToTheSameOptions) {
  const auto& table = BuilderOptionTable();
  ReconstructOptions changed;
  table.ApplyTexts(changed,
                   {"patch.ncc_threshold=0.65", "proxy.final_voxel_size=0.0012", "method=none",
                    "soil.enabled=false"},
                   "--set");
  const std::string text = table.ToToml(changed);
  const auto file = std::filesystem::path(::testing::TempDir()) / "builder.toml";
  std::ofstream(file) << text;
  const ReconstructOptions read = table.Load(ReconstructOptions{}, {file.string()}, {});
  EXPECT_EQ(table.ToToml(read), text);
  EXPECT_EQ(read.patch.ncc_threshold, 0.65);
  EXPECT_EQ(read.proxy.final_voxel_size, 0.0012);
  EXPECT_EQ(read.method, MvsMethod::kNone);
  EXPECT_NE(table.ToToml(ReconstructOptions{}), text);
}

}  // namespace
}  // namespace avc::builder
