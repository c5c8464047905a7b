// report.html in Debian's chromium, headless with software WebGL (SwiftShader): the page's script
// runs without error, draws its first WebGL frame, and the 3-D view shows the model.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "report/report_html.h"
#include "tests/report/report_test_scan.h"
#include "tests/support/test_support.h"

namespace avc::report {
namespace {

namespace fs = std::filesystem;

constexpr char kChromium[] = "/usr/bin/chromium";

// Runs headless chromium on the page with `what` (--dump-dom, --screenshot=FILE); stdout and
// stderr (the browser's log, with the page's console) go to files in dir.
int RunChromium(const fs::path& dir, const std::string& what, const std::string& name) {
  const std::string command =
      std::string("timeout 100 ") + kChromium +
      " --headless=new --no-sandbox --disable-gpu --use-gl=swiftshader"
      " --enable-unsafe-swiftshader --no-first-run --user-data-dir=" +
      (dir / "profile").string() +
      " --window-size=1200,900 --virtual-time-budget=5000 --enable-logging=stderr --v=0 " + what +
      " file://" + (dir / "report.html").string() + " >" + (dir / (name + ".out")).string() +
      " 2>" + (dir / (name + ".log")).string();
  return std::system(command.c_str());
}

class ReportBrowser : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(kChromium)) GTEST_SKIP() << kChromium << " is absent (Debian package chromium)";
    testing::WriteTestScan(dir_.path(), testing::WavySheet(40));
    WriteReportHtml(dir_.path());
  }
  testing::TempDir dir_{"avc-report-browser"};
};

TEST_F(ReportBrowser, RendersTheModelWithWebGlAndNoScriptError) {
  ASSERT_EQ(RunChromium(dir_.path(), "--dump-dom", "dom"), 0)
      << testing::ReadFile(dir_ / "dom.log");
  const std::string dom = testing::ReadFile(dir_ / "dom.out");
  const std::string log = testing::ReadFile(dir_ / "dom.log");
  EXPECT_EQ(dom.find("data-js-error="), std::string::npos) << dom.substr(0, 2000);
  EXPECT_EQ(log.find("Uncaught"), std::string::npos) << log;
  EXPECT_EQ(log.find("ERROR:CONSOLE"), std::string::npos) << log;
  EXPECT_EQ(log.find("\"THREE."), std::string::npos) << log;  // three.js's own complaints
  EXPECT_NE(dom.find("data-rendered=\"webgl\""), std::string::npos) << log;
}

TEST_F(ReportBrowser, TheThreeDViewIsNotBlank) {
  const fs::path shot = dir_ / "shot.png";
  ASSERT_EQ(RunChromium(dir_.path(), "--screenshot=" + shot.string(), "shot"), 0)
      << testing::ReadFile(dir_ / "shot.log");
  const cv::Mat image = cv::imread(shot.string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty()) << shot;
  // The view's clear colour (#f4f6f8) occurs nowhere else: its bounding box is the canvas.
  const cv::Vec3b background(0xf8, 0xf6, 0xf4);
  int x0 = image.cols, y0 = image.rows, x1 = -1, y1 = -1;
  for (int y = 0; y < image.rows; ++y) {
    for (int x = 0; x < image.cols; ++x) {
      if (image.at<cv::Vec3b>(y, x) != background) continue;
      x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
    }
  }
  ASSERT_GT(x1 - x0, 200) << "no 3-D view found in the screenshot";
  ASSERT_GT(y1 - y0, 100) << "the 3-D view is cut off";
  int drawn = 0;
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const cv::Vec3b p = image.at<cv::Vec3b>(y, x);
      drawn += std::abs(p[0] - background[0]) + std::abs(p[1] - background[1]) +
                   std::abs(p[2] - background[2]) >
               40;
    }
  }
  const double area = double(x1 - x0 + 1) * (y1 - y0 + 1);
  EXPECT_GT(drawn / area, 0.02) << drawn << " model pixels in " << area;
}

}  // namespace
}  // namespace avc::report
