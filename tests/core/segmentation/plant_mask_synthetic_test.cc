// SegmentPlant, Otsu and the cleanup on images whose answer is known by construction, and its
// refusals of bad input.

#include <gtest/gtest.h>

#include <limits>
#include <opencv2/imgproc.hpp>
#include <random>
#include <stdexcept>

#include "core/segmentation/mask_cleanup.h"
#include "core/segmentation/otsu.h"
#include "core/segmentation/plant_mask.h"
#include "tests/core/segmentation/mask_metrics.h"

namespace avc::segmentation {
namespace {

using testing::MaskIoU;

// Deterministic pixel noise of +-amplitude grey levels (no library distributions).
void AddNoise(cv::Mat& bgr, int amplitude, uint32_t seed) {
  std::mt19937 rng(seed);
  for (int y = 0; y < bgr.rows; ++y) {
    for (int x = 0; x < bgr.cols; ++x) {
      for (int c = 0; c < 3; ++c) {
        const int delta = static_cast<int>(rng() % (2 * amplitude + 1)) - amplitude;
        uchar& v = bgr.at<cv::Vec3b>(y, x)[c];
        v = cv::saturate_cast<uchar>(v + delta);
      }
    }
  }
}

TEST(Otsu, SplitsTwoLevelsBetweenThemWithFullSeparability) {
  cv::Mat values(10, 10, CV_32FC1, cv::Scalar(0.2f));
  values.rowRange(0, 3).setTo(0.8f);
  const OtsuSplit split = OtsuThreshold(values, 256);
  EXPECT_GT(split.threshold, 0.2);
  EXPECT_LT(split.threshold, 0.8);
  EXPECT_NEAR(split.separability, 1.0, 1e-9);
  EXPECT_NEAR(SplitSeparability(values, 0.5), 1.0, 1e-9);
  EXPECT_EQ(SplitSeparability(values, 0.9), 0.0);
}

TEST(Otsu, ConstantImageHasNoSplit) {
  const cv::Mat values(5, 7, CV_32FC1, cv::Scalar(0.4f));
  const OtsuSplit split = OtsuThreshold(values, 256);
  EXPECT_EQ(split.separability, 0.0);
  EXPECT_EQ(cv::countNonZero(values > split.threshold), 0);
}

TEST(Otsu, RefusesNonFiniteValues) {
  cv::Mat values(4, 4, CV_32FC1, cv::Scalar(1.0f));
  values.at<float>(2, 3) = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(OtsuThreshold(values, 256), std::invalid_argument);
  EXPECT_THROW(OtsuThreshold(cv::Mat(4, 4, CV_8UC1), 256), std::invalid_argument);
}

TEST(SegmentPlant, GreenDiscOnGrey) {
  cv::Mat image(240, 320, CV_8UC3, cv::Scalar(90, 90, 90));
  cv::Mat truth(image.size(), CV_8UC1, cv::Scalar(0));
  cv::circle(image, {160, 120}, 50, cv::Scalar(40, 110, 50), cv::FILLED);
  cv::circle(truth, {160, 120}, 50, cv::Scalar(255), cv::FILLED);
  AddNoise(image, 6, 1);
  const MaskResult result = SegmentPlant(image);
  EXPECT_NE(result.method, MaskMethod::kAuto);
  EXPECT_GT(result.separability, 0.9);
  EXPECT_GT(MaskIoU(result.mask, truth), 0.98);
}

TEST(SegmentPlant, GreyObjectOnBlackUsesBackgroundDistance) {
  cv::Mat image(240, 320, CV_8UC3, cv::Scalar(12, 12, 12));
  cv::Mat truth(image.size(), CV_8UC1, cv::Scalar(0));
  cv::ellipse(image, {150, 130}, {70, 45}, 20, 0, 360, cv::Scalar(170, 180, 185), cv::FILLED);
  cv::ellipse(truth, {150, 130}, {70, 45}, 20, 0, 360, cv::Scalar(255), cv::FILLED);
  AddNoise(image, 8, 3);
  const MaskResult result = SegmentPlant(image);
  EXPECT_EQ(result.method, MaskMethod::kBackgroundDistance);
  EXPECT_GT(MaskIoU(result.mask, truth), 0.97);
}

TEST(SegmentPlant, ThinLeafSurvivesCleanup) {
  // A 2 px wide green blade on grey, with a broad leaf elsewhere so the blade is not the
  // largest component, plus isolated noise specks that must go.
  cv::Mat image(240, 320, CV_8UC3, cv::Scalar(100, 100, 100));
  cv::Mat blade(image.size(), CV_8UC1, cv::Scalar(0));
  cv::rectangle(blade, cv::Rect(40, 30, 2, 180), cv::Scalar(255), cv::FILLED);
  image.setTo(cv::Scalar(45, 120, 55), blade);
  cv::circle(image, {220, 120}, 60, cv::Scalar(45, 120, 55), cv::FILLED);
  for (int i = 0; i < 10; ++i) image.at<cv::Vec3b>(20 + 20 * i, 120) = cv::Vec3b(45, 120, 55);
  AddNoise(image, 4, 2);

  MaskOptions green;
  green.method = MaskMethod::kExcessGreen;
  for (const MaskOptions& options : {MaskOptions{}, green}) {
    const MaskResult result = SegmentPlant(image, options);
    EXPECT_GT(testing::CoveredFraction(result.mask, blade), 0.99);
    for (int i = 0; i < 10; ++i) EXPECT_EQ(result.mask.at<uchar>(20 + 20 * i, 120), 0) << i;
  }
}

TEST(SegmentPlant, OneGreenPixelWideLineSurvives) {
  cv::Mat image(240, 320, CV_8UC3, cv::Scalar(100, 100, 100));
  cv::line(image, {30, 200}, {290, 40}, cv::Scalar(45, 120, 55), 1);
  cv::Mat line_mask(image.size(), CV_8UC1, cv::Scalar(0));
  cv::line(line_mask, {30, 200}, {290, 40}, cv::Scalar(255), 1);
  const MaskResult result = SegmentPlant(image);
  EXPECT_EQ(testing::CoveredFraction(result.mask, line_mask), 1.0);
  // Closing may fill the staircase corners of the line, but adds nothing far from it.
  cv::Mat near_line;
  cv::dilate(line_mask, near_line, cv::Mat::ones(3, 3, CV_8U));
  EXPECT_EQ(cv::countNonZero(result.mask & ~near_line), 0);
}

TEST(SegmentPlant, SingleColourImageGivesEmptyMask) {
  for (const cv::Scalar& colour : {cv::Scalar(0, 0, 0), cv::Scalar(60, 140, 50),
                                   cv::Scalar(128, 128, 128), cv::Scalar(255, 255, 255)}) {
    const cv::Mat image(120, 160, CV_8UC3, colour);
    const MaskResult result = SegmentPlant(image);
    EXPECT_EQ(result.mask.size(), image.size());
    EXPECT_EQ(result.mask.type(), CV_8UC1);
    EXPECT_EQ(cv::countNonZero(result.mask), 0);
    EXPECT_EQ(result.separability, 0.0);
  }
}

TEST(SegmentPlant, GivenThresholdOverridesOtsu) {
  cv::Mat image(100, 100, CV_8UC3, cv::Scalar(100, 100, 100));
  cv::rectangle(image, cv::Rect(20, 20, 30, 30), cv::Scalar(80, 120, 80), cv::FILLED);
  MaskOptions options;
  options.method = MaskMethod::kExcessGreen;
  options.threshold = 0.5;  // above the square's ExG of 0.2: nothing is plant
  const MaskResult result = SegmentPlant(image, options);
  EXPECT_EQ(result.threshold, 0.5);
  EXPECT_EQ(cv::countNonZero(result.mask), 0);
  options.threshold = 0.1;
  EXPECT_EQ(cv::countNonZero(SegmentPlant(image, options).mask), 30 * 30);
}

TEST(SegmentPlant, RefusesBadInput) {
  EXPECT_THROW(SegmentPlant(cv::Mat()), std::invalid_argument);
  EXPECT_THROW(SegmentPlant(cv::Mat(10, 10, CV_16UC3, cv::Scalar(0))), std::invalid_argument);
  EXPECT_THROW(SegmentPlant(cv::Mat(10, 10, CV_16UC1, cv::Scalar(0))), std::invalid_argument);
  EXPECT_THROW(SegmentPlant(cv::Mat(10, 10, CV_8UC1, cv::Scalar(0))), std::invalid_argument);
  try {
    SegmentPlant(cv::Mat(10, 10, CV_16UC3, cv::Scalar(0)));
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("CV_8UC3"), std::string::npos) << error.what();
  }
  const cv::Mat image(10, 10, CV_8UC3, cv::Scalar(1, 2, 3));
  MaskOptions bad;
  bad.histogram_bins = 1;
  EXPECT_THROW(SegmentPlant(image, bad), std::invalid_argument);
  bad = {};
  bad.dark_fraction = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(SegmentPlant(image, bad), std::invalid_argument);
  bad = {};
  bad.threshold = std::numeric_limits<double>::infinity();
  EXPECT_THROW(SegmentPlant(image, bad), std::invalid_argument);
}

TEST(CleanMask, ClosesPinHolesAndDropsSpecks) {
  cv::Mat mask(100, 100, CV_8UC1, cv::Scalar(0));
  cv::rectangle(mask, cv::Rect(10, 10, 60, 60), cv::Scalar(255), cv::FILLED);
  mask.at<uchar>(40, 40) = 0;    // pin hole
  mask.at<uchar>(90, 90) = 255;  // speck
  CleanupOptions options;
  const cv::Mat cleaned = CleanMask(mask, options);
  EXPECT_EQ(cleaned.at<uchar>(40, 40), 255);
  EXPECT_EQ(cleaned.at<uchar>(90, 90), 0);
  EXPECT_EQ(cv::countNonZero(cleaned), 60 * 60);
}

}  // namespace
}  // namespace avc::segmentation
