// FillMissingMasks: computes only the missing masks, keeps given ones, is the same however the
// views are scheduled, and names the view at fault.

#include "core/segmentation/fill_masks.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

namespace avc::segmentation {
namespace {

dataset::View GreenBlobView(int index) {
  dataset::View view;
  view.name = "view_" + std::to_string(index) + ".png";
  view.image = cv::Mat(120, 160, CV_8UC3, cv::Scalar(90, 90, 90));
  cv::circle(view.image, {40 + 8 * index, 60}, 20 + index, cv::Scalar(40, 120, 50), cv::FILLED);
  return view;
}

dataset::ViewSet MakeSet(int count) {
  dataset::ViewSet set;
  set.format = "live";
  for (int i = 0; i < count; ++i) set.views.push_back(GreenBlobView(i));
  return set;
}

TEST(FillMissingMasks, ComputesMissingAndKeepsGiven) {
  dataset::ViewSet set = MakeSet(6);
  const cv::Mat given(120, 160, CV_8UC1, cv::Scalar(0));
  given(cv::Rect(0, 0, 16, 12)).setTo(255);
  set.views[2].mask = given.clone();
  const MaskSummary summary = FillMissingMasks(set);
  EXPECT_EQ(summary.computed, 5);
  EXPECT_EQ(summary.given, 1);
  ASSERT_EQ(summary.views.size(), 6u);
  EXPECT_TRUE(summary.views[2].given);
  EXPECT_EQ(cv::norm(set.views[2].mask, given, cv::NORM_INF), 0);
  EXPECT_NEAR(summary.views[2].plant_fraction, 0.01, 1e-12);
  for (int i : {0, 1, 3, 4, 5}) {
    const dataset::View& view = set.views[static_cast<size_t>(i)];
    EXPECT_EQ(summary.views[static_cast<size_t>(i)].view, view.name);
    EXPECT_FALSE(summary.views[static_cast<size_t>(i)].given);
    EXPECT_NE(summary.views[static_cast<size_t>(i)].method, MaskMethod::kAuto);
    ASSERT_EQ(view.mask.size(), view.image.size());
    const double disc = CV_PI * (20 + i) * (20 + i) / (120.0 * 160.0);
    EXPECT_NEAR(summary.views[static_cast<size_t>(i)].plant_fraction, disc, 0.1 * disc) << i;
  }
}

TEST(FillMissingMasks, SameResultAsOneViewAtATime) {
  dataset::ViewSet set = MakeSet(8);
  FillMissingMasks(set);
  for (const dataset::View& view : set.views) {
    const cv::Mat alone = SegmentPlant(view.image).mask;
    EXPECT_EQ(cv::norm(alone, view.mask, cv::NORM_INF), 0) << view.name;
  }
}

std::string ErrorOf(dataset::ViewSet& set) {
  try {
    FillMissingMasks(set);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(FillMissingMasks, NamesTheViewAtFault) {
  dataset::ViewSet set = MakeSet(3);
  set.views[1].mask = cv::Mat(60, 80, CV_8UC1, cv::Scalar(255));
  std::string message = ErrorOf(set);
  EXPECT_NE(message.find("view_1.png"), std::string::npos) << message;
  EXPECT_NE(message.find("mask"), std::string::npos) << message;
  EXPECT_TRUE(set.views[0].mask.empty()) << "nothing is changed on failure";

  set = MakeSet(3);
  set.views[2].image = cv::Mat();
  message = ErrorOf(set);
  EXPECT_NE(message.find("view_2.png"), std::string::npos) << message;
  EXPECT_NE(message.find("empty"), std::string::npos) << message;

  set = MakeSet(3);
  set.views[0].image.convertTo(set.views[0].image, CV_16U);
  message = ErrorOf(set);
  EXPECT_NE(message.find("view_0.png"), std::string::npos) << message;

  set = MakeSet(2);
  set.views[1].mask = cv::Mat(120, 160, CV_16UC1, cv::Scalar(0));
  message = ErrorOf(set);
  EXPECT_NE(message.find("view_1.png"), std::string::npos) << message;
}

TEST(FillMissingMasks, EmptySetIsFine) {
  dataset::ViewSet set;
  const MaskSummary summary = FillMissingMasks(set);
  EXPECT_EQ(summary.computed + summary.given, 0);
}

}  // namespace
}  // namespace avc::segmentation
