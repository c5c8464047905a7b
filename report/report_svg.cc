#include "report/report_svg.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgcodecs.hpp>

#include "core/util/web_text.h"
#include "report/report_encode.h"

namespace avc::report {

std::string MeshViewSvg(const geometry::Mesh& mesh,
                        const std::vector<std::array<uint8_t, 3>>& face_colours, MeshView view,
                        int size_px) {
  std::vector<uint8_t> png;
  cv::imencode(".png", RenderMeshView(mesh, face_colours, view, size_px), png);
  return fmt::format(
      "<svg class=\"mesh-view\" width=\"{0}\" height=\"{0}\" viewBox=\"0 0 {0} {0}\" "
      "role=\"img\" aria-label=\"mesh, {1} view\">\n"
      "<image width=\"{0}\" height=\"{0}\" href=\"data:image/png;base64,{2}\"/>\n"
      "<text x=\"6\" y=\"16\" font-size=\"13\" fill=\"#333\">{1}</text>\n</svg>\n",
      size_px, NameOf(view), Base64Encode(png));
}

std::string BarChartSvg(const std::vector<std::pair<std::string, double>>& bars,
                        const std::string& unit) {
  const int row = 20, label_width = 150, bar_width = 380, width = label_width + bar_width + 90;
  const int height = row * static_cast<int>(bars.size()) + 4;
  double largest = 0;
  for (const auto& [label, value] : bars) largest = std::max(largest, value);
  std::string svg = fmt::format(
      "<svg class=\"bar-chart\" width=\"{0}\" "
      "height=\"{1}\" viewBox=\"0 0 {0} {1}\" role=\"img\">\n",
      width, height);
  for (size_t i = 0; i < bars.size(); ++i) {
    const auto& [label, value] = bars[i];
    const double length = largest > 0 ? std::max(0.0, value) / largest * bar_width : 0;
    const int y = static_cast<int>(i) * row + 2;
    svg += fmt::format(
        "<text x=\"{}\" y=\"{}\" font-size=\"12\" text-anchor=\"end\">{}</text>"
        "<rect x=\"{}\" y=\"{}\" width=\"{:.1f}\" height=\"{}\" fill=\"#4a7fb5\"/>"
        "<text x=\"{:.1f}\" y=\"{}\" font-size=\"12\">{:.2f} {}</text>\n",
        label_width - 6, y + 13, EscapeHtml(label), label_width, y + 2, length, row - 6,
        label_width + length + 4, y + 13, value, EscapeHtml(unit));
  }
  return svg + "</svg>\n";
}

std::string LineChartSvg(const std::vector<double>& fractions, const std::string& x_label,
                         const std::string& y_label, std::pair<double, double> marked) {
  const int left = 48, top = 10, plot_w = 420, plot_h = 200, width = left + plot_w + 20,
            height = top + plot_h + 40;
  const double n = std::max<double>(1, static_cast<double>(fractions.size()));
  const auto x_of = [&](double x) { return left + x / n * plot_w; };
  const auto y_of = [&](double f) { return top + (1 - std::clamp(f, 0.0, 1.0)) * plot_h; };
  std::string svg = fmt::format(
      "<svg class=\"line-chart\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
      "role=\"img\">\n",
      width, height);
  for (int percent = 0; percent <= 100; percent += 25) {
    const double y = y_of(percent / 100.0);
    svg += fmt::format(
        "<line x1=\"{}\" y1=\"{:.1f}\" x2=\"{}\" y2=\"{:.1f}\" stroke=\"#ddd\"/>"
        "<text x=\"{}\" y=\"{:.1f}\" font-size=\"11\" text-anchor=\"end\">{} %</text>\n",
        left, y, left + plot_w, y, left - 4, y + 4, percent);
  }
  svg += fmt::format(
      "<text x=\"{}\" y=\"{}\" font-size=\"12\" text-anchor=\"middle\">{} (1 .. {})</text>"
      "<text x=\"12\" y=\"{}\" font-size=\"12\" text-anchor=\"middle\" "
      "transform=\"rotate(-90 12 {})\">{}</text>\n",
      left + plot_w / 2, top + plot_h + 30, EscapeHtml(x_label), fractions.size(), top + plot_h / 2,
      top + plot_h / 2, EscapeHtml(y_label));
  std::string points;
  for (size_t i = 0; i < fractions.size(); ++i) {
    points += fmt::format("{:.1f},{:.1f} ", x_of(static_cast<double>(i + 1)), y_of(fractions[i]));
  }
  svg +=
      "<polyline fill=\"none\" stroke=\"#4a7fb5\" stroke-width=\"2\" points=\"" + points + "\"/>\n";
  if (marked.first > 0) {
    svg += fmt::format(
        "<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"5\" fill=\"#c0504d\"/>"
        "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"11\" text-anchor=\"end\">kept: {:.0f} "
        "images, {:.1f} %</text>\n",
        x_of(marked.first), y_of(marked.second), x_of(marked.first) - 8, y_of(marked.second) + 18,
        marked.first, 100 * marked.second);
  }
  return svg + "</svg>\n";
}

}  // namespace avc::report
