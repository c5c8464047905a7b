// The cell colour model of Phase 2: chromaticity, so a leaf's shades agree and other hues do not.

#include "core/surface/colour_model.h"

#include <gtest/gtest.h>

namespace avc::surface {
namespace {

using Rgb = Eigen::Matrix<uint8_t, 3, 1>;

std::vector<Rgb> LeafGreens() {
  // A green leaf's points in light and shade: the same hue at several brightnesses.
  return {Rgb(50, 140, 60), Rgb(48, 138, 58), Rgb(25, 70, 30), Rgb(75, 210, 90), Rgb(52, 142, 61)};
}

TEST(ColourModel, ShadesOfTheCellsColourAgreeOtherHuesDoNot) {
  const std::optional<ColourModel> model = ColourModel::Fit(LeafGreens());
  ASSERT_TRUE(model.has_value());
  EXPECT_NEAR(model->mean().x(), 50.0 / 250.0, 0.01);
  EXPECT_NEAR(model->mean().y(), 140.0 / 250.0, 0.01);
  EXPECT_FLOAT_EQ(model->tolerance(), 0.03f);  // the floor: these greens hardly differ
  // BGR: the same green in shade and in light, then a red stem, a brown soil, a yellow leaf.
  EXPECT_TRUE(model->Agrees(cv::Vec3b(30, 70, 25)));
  EXPECT_TRUE(model->Agrees(cv::Vec3b(90, 210, 75)));
  EXPECT_FALSE(model->Agrees(cv::Vec3b(40, 40, 160)));
  EXPECT_FALSE(model->Agrees(cv::Vec3b(40, 80, 120)));
  EXPECT_FALSE(model->Agrees(cv::Vec3b(40, 180, 180)));
  // Too dark for a hue: no evidence either way.
  EXPECT_TRUE(model->Agrees(cv::Vec3b(10, 2, 20)));
}

TEST(ColourModel, TheToleranceFollowsTheCellsOwnSpread) {
  std::vector<Rgb> mixed = LeafGreens();
  mixed.push_back(Rgb(120, 140, 40));  // yellowish points in the same cell
  mixed.push_back(Rgb(30, 140, 110));  // and bluish ones
  const std::optional<ColourModel> model = ColourModel::Fit(mixed);
  ASSERT_TRUE(model.has_value());
  EXPECT_GT(model->tolerance(), 0.1f);
  ColourModelOptions strict;
  strict.tolerance_factor = 1.0;
  EXPECT_LT(ColourModel::Fit(mixed, strict)->tolerance(), model->tolerance());
}

TEST(ColourModel, TooFewUsableColoursGiveNoModel) {
  EXPECT_FALSE(ColourModel::Fit({}).has_value());
  EXPECT_FALSE(ColourModel::Fit({Rgb(50, 140, 60), Rgb(50, 140, 60)}).has_value());
  // Dark colours do not count.
  EXPECT_FALSE(ColourModel::Fit({Rgb(50, 140, 60), Rgb(50, 140, 60), Rgb(5, 10, 5)}).has_value());
}

}  // namespace
}  // namespace avc::surface
