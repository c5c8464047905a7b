#include "core/eval/report_plot.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

namespace avc::eval {
namespace {

constexpr int kPanelWidth = 480;
constexpr int kHeight = 400;
constexpr int kBins = 40;
// Plot area inside a panel.
constexpr int kLeft = 60, kRight = 20, kTop = 40, kBottom = 60;

const cv::Scalar kBlack(0, 0, 0);
const cv::Scalar kGrey(170, 170, 170);
const cv::Scalar kBlue(180, 100, 30);    // accuracy / precision (BGR)
const cv::Scalar kOrange(30, 140, 240);  // completeness / recall
const cv::Scalar kGreen(60, 150, 40);    // F-score

void Text(cv::Mat& image, const std::string& text, cv::Point at, double scale = 0.42,
          const cv::Scalar& colour = kBlack) {
  cv::putText(image, text, at, cv::FONT_HERSHEY_SIMPLEX, scale, colour, 1, cv::LINE_AA);
}

// Maps data coordinates of a panel to pixels.
struct Axes {
  int x0;  // panel's left edge
  double x_max, y_max;
  cv::Point At(double x, double y) const {
    const double width = kPanelWidth - kLeft - kRight;
    const double height = kHeight - kTop - kBottom;
    return {x0 + kLeft + static_cast<int>(std::lround(x / x_max * width)),
            kHeight - kBottom - static_cast<int>(std::lround(y / y_max * height))};
  }
};

void DrawFrame(cv::Mat& image, const Axes& axes, const std::string& title,
               const std::string& x_label) {
  cv::rectangle(image, axes.At(0, axes.y_max), axes.At(axes.x_max, 0), kBlack, 1);
  Text(image, title, {axes.x0 + kLeft, kTop - 14}, 0.5);
  Text(image, x_label, {axes.x0 + kLeft + 120, kHeight - 15});
}

// A round tick spacing (1, 2 or 5 times a power of ten) giving at most max_ticks intervals.
double NiceStep(double range, int max_ticks) {
  const double raw = range / max_ticks;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  for (double multiple : {1.0, 2.0, 5.0}) {
    if (multiple * magnitude >= raw) return multiple * magnitude;
  }
  return 10 * magnitude;
}

std::vector<double> Histogram(const std::vector<double>& values, double bin_width) {
  std::vector<double> fractions(kBins, 0.0);
  if (values.empty()) return fractions;
  for (double v : values) {
    // The last bin also holds everything beyond the range.
    const int bin = std::min(kBins - 1, static_cast<int>(v / bin_width));
    fractions[static_cast<size_t>(bin)] += 1;
  }
  for (double& f : fractions) f /= static_cast<double>(values.size());
  return fractions;
}

void DrawHistograms(cv::Mat& image, const EvalResult& result) {
  const double x_max_m =
      std::max({result.thresholds.back(), result.accuracy.p90, result.completeness.p90, 1e-9}) *
      1.25;
  const double bin = x_max_m / kBins;
  const std::vector<double> accuracy = Histogram(result.accuracy_distances, bin);
  const std::vector<double> completeness = Histogram(result.completeness_distances, bin);
  const double peak = std::max(*std::max_element(accuracy.begin(), accuracy.end()),
                               *std::max_element(completeness.begin(), completeness.end()));
  const Axes axes{0, x_max_m * 1e3, std::max(peak * 1.1, 1e-3)};
  for (double threshold : result.thresholds) {
    cv::line(image, axes.At(threshold * 1e3, 0), axes.At(threshold * 1e3, axes.y_max), kGrey, 1);
  }
  for (int b = 0; b < kBins; ++b) {
    const double left = b * bin * 1e3, middle = (b + 0.5) * bin * 1e3, right = (b + 1) * bin * 1e3;
    cv::rectangle(image, axes.At(left, accuracy[static_cast<size_t>(b)]), axes.At(middle, 0), kBlue,
                  cv::FILLED);
    cv::rectangle(image, axes.At(middle, completeness[static_cast<size_t>(b)]), axes.At(right, 0),
                  kOrange, cv::FILLED);
  }
  DrawFrame(image, axes, "Distance histograms (last bin: beyond)", "distance (mm)");
  const double x_step = NiceStep(axes.x_max, 5);
  for (int k = 0; k * x_step <= axes.x_max * (1 + 1e-9); ++k) {
    Text(image, fmt::format("{:g}", k * x_step), axes.At(k * x_step, 0) + cv::Point(-8, 18));
  }
  const double y_step = NiceStep(axes.y_max, 4);
  for (int k = 0; k * y_step <= axes.y_max * (1 + 1e-9); ++k) {
    Text(image, fmt::format("{:g}", k * y_step), axes.At(0, k * y_step) + cv::Point(-45, 4));
  }
  const int legend_x = kPanelWidth - kRight - 200;
  cv::rectangle(image, {legend_x, kTop + 8}, {legend_x + 10, kTop + 18}, kBlue, cv::FILLED);
  Text(image, "accuracy (rec -> GT)", {legend_x + 15, kTop + 18});
  cv::rectangle(image, {legend_x, kTop + 26}, {legend_x + 10, kTop + 36}, kOrange, cv::FILLED);
  Text(image, "completeness (GT -> rec)", {legend_x + 15, kTop + 36});
}

void DrawScores(cv::Mat& image, const EvalResult& result) {
  // Thresholds usually grow geometrically: space them evenly by rank.
  const size_t n = result.scores.size();
  const Axes axes{kPanelWidth, static_cast<double>(n), 1.0};
  auto x_of = [](size_t i) { return static_cast<double>(i) + 0.5; };
  for (int tick = 0; tick <= 4; ++tick) {
    const double y = tick / 4.0;
    cv::line(image, axes.At(0, y), axes.At(axes.x_max, y), kGrey, 1);
    Text(image, fmt::format("{:.2f}", y), axes.At(0, y) + cv::Point(-45, 4));
  }
  const std::pair<double ThresholdScore::*, cv::Scalar> curves[] = {
      {&ThresholdScore::precision, kBlue},
      {&ThresholdScore::recall, kOrange},
      {&ThresholdScore::fscore, kGreen}};
  for (const auto& [member, colour] : curves) {
    for (size_t i = 0; i < n; ++i) {
      const cv::Point point = axes.At(x_of(i), result.scores[i].*member);
      cv::circle(image, point, 4, colour, cv::FILLED, cv::LINE_AA);
      if (i > 0) {
        cv::line(image, axes.At(x_of(i - 1), result.scores[i - 1].*member), point, colour, 2,
                 cv::LINE_AA);
      }
    }
  }
  for (size_t i = 0; i < n; ++i) {
    Text(image, fmt::format("{:g}", result.scores[i].threshold * 1e3),
         axes.At(x_of(i), 0) + cv::Point(-10, 18));
  }
  DrawFrame(image, axes, "Precision, recall and F-score", "threshold (mm)");
  const int legend_x = kPanelWidth + kLeft + 10;
  const std::pair<const char*, cv::Scalar> legend[] = {
      {"precision", kBlue}, {"recall", kOrange}, {"F-score", kGreen}};
  for (int i = 0; i < 3; ++i) {
    const int y = kHeight - kBottom - 60 + 16 * i;
    cv::line(image, {legend_x, y - 4}, {legend_x + 16, y - 4}, legend[i].second, 2);
    Text(image, legend[i].first, {legend_x + 22, y});
  }
}

}  // namespace

std::vector<uint8_t> RenderErrorPlotPng(const EvalResult& result) {
  if (result.thresholds.empty() || result.scores.size() != result.thresholds.size()) {
    throw std::invalid_argument("error plot: the result has no scores to draw");
  }
  cv::Mat image(kHeight, 2 * kPanelWidth, CV_8UC3, cv::Scalar(255, 255, 255));
  DrawHistograms(image, result);
  DrawScores(image, result);
  std::vector<uint8_t> png;
  if (!cv::imencode(".png", image, png))
    throw std::runtime_error("error plot: PNG encoding failed");
  return png;
}

}  // namespace avc::eval
