// Named parameter overrides of the builder (avc reconstruct --set).

#include "services/builder/option_overrides.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace avc::builder {
namespace {

std::string ErrorOf(const std::string& assignment) {
  ReconstructOptions options;
  try {
    ApplyOverride(assignment, &options);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(OptionOverrides, SetsIntegerAndRealFieldsOfEachSection) {
  ReconstructOptions options;
  ApplyOverride("patch.window=7", &options);
  ApplyOverride("patch.ncc_threshold=0.8", &options);
  ApplyOverride("sweep.best_k=3", &options);
  ApplyOverride("proxy.background_votes_allowed=2", &options);
  ApplyOverride("soil.min_elevation_deg=40", &options);
  EXPECT_DOUBLE_EQ(options.soil.min_elevation_deg, 40.0);
  EXPECT_EQ(options.patch.window, 7);
  EXPECT_DOUBLE_EQ(options.patch.ncc_threshold, 0.8);
  EXPECT_EQ(options.sweep.best_k, 3);
  EXPECT_EQ(options.proxy.background_votes_allowed, 2);
  const auto names = OverrideNames();
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
  EXPECT_NE(std::find(names.begin(), names.end(), "patch.min_texture"), names.end());
}

TEST(OptionOverrides, RefusesUnknownNamesBadNumbersAndInvalidValuesUnchanged) {
  EXPECT_NE(ErrorOf("patch.windw=7").find("unknown setting 'patch.windw'"), std::string::npos);
  EXPECT_NE(ErrorOf("patch.window").find("expected section.field=value"), std::string::npos);
  EXPECT_NE(ErrorOf("patch.window=7.5").find("not a number"), std::string::npos);
  EXPECT_NE(ErrorOf("patch.window=6").find("PatchMvsOptions.window"), std::string::npos);
  EXPECT_NE(ErrorOf("soil.outer_radius=0.01").find("SoilLevelOptions.outer_radius"),
            std::string::npos);
  ReconstructOptions options;
  EXPECT_THROW(ApplyOverride("patch.window=6", &options), std::invalid_argument);
  EXPECT_EQ(options.patch.window, ReconstructOptions{}.patch.window);
}

}  // namespace
}  // namespace avc::builder
