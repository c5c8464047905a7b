// The Middlebury silhouette recipe: threshold on [0, 1] intensity, dilate, erode with discs.

#include "core/segmentation/threshold_silhouette.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace avc::segmentation {
namespace {

TEST(ThresholdSilhouette, ThresholdIsStrictOnUnitIntensity) {
  cv::Mat grey(1, 4, CV_8UC1);
  grey.at<uchar>(0, 0) = 48;  // 0.188
  grey.at<uchar>(0, 1) = 49;  // 0.192
  grey.at<uchar>(0, 2) = 0;
  grey.at<uchar>(0, 3) = 255;
  const cv::Mat mask = ThresholdSilhouette(grey, 0.19, 0, 0);
  EXPECT_EQ(mask.at<uchar>(0, 0), 0);
  EXPECT_EQ(mask.at<uchar>(0, 1), 255);
  EXPECT_EQ(mask.at<uchar>(0, 2), 0);
  EXPECT_EQ(mask.at<uchar>(0, 3), 255);
}

TEST(ThresholdSilhouette, DilateThenErodeFillsGapsAndGrowsByTheDifference) {
  cv::Mat image(200, 200, CV_8UC3, cv::Scalar(10, 10, 10));
  cv::rectangle(image, cv::Rect(50, 50, 100, 100), cv::Scalar(200, 200, 200), cv::FILLED);
  cv::line(image, {100, 50}, {100, 149}, cv::Scalar(0, 0, 0), 5);  // a dark 5 px crack
  const cv::Mat mask = ThresholdSilhouette(image, 0.19, 10, 7);
  EXPECT_EQ(mask.type(), CV_8UC1);
  EXPECT_EQ(mask.at<uchar>(100, 100), 255);  // the crack is closed
  // Net growth of 10 - 7 = 3 px at a straight edge: the square spans 47..152 along its middle.
  EXPECT_EQ(mask.at<uchar>(100, 47), 255);
  EXPECT_EQ(mask.at<uchar>(100, 46), 0);
  EXPECT_EQ(mask.at<uchar>(100, 152), 255);
  EXPECT_EQ(mask.at<uchar>(100, 153), 0);
}

TEST(ThresholdSilhouette, RefusesBadInput) {
  const cv::Mat image(10, 10, CV_8UC3, cv::Scalar(0));
  EXPECT_THROW(ThresholdSilhouette(cv::Mat(), 0.19, 10, 7), std::invalid_argument);
  EXPECT_THROW(ThresholdSilhouette(cv::Mat(10, 10, CV_16UC1), 0.19, 10, 7), std::invalid_argument);
  EXPECT_THROW(ThresholdSilhouette(image, 1.5, 10, 7), std::invalid_argument);
  EXPECT_THROW(ThresholdSilhouette(image, std::nan(""), 10, 7), std::invalid_argument);
  EXPECT_THROW(ThresholdSilhouette(image, 0.19, -1, 7), std::invalid_argument);
}

}  // namespace
}  // namespace avc::segmentation
