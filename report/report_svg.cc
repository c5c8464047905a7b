#include "report/report_svg.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "report/report_encode.h"

namespace avc::report {
namespace {

struct Axes {
  Eigen::Vector3f right, up, towards_viewer;
};

Axes AxesOf(MeshView view) {
  switch (view) {
    case MeshView::kFront:
      return {{1, 0, 0}, {0, 0, 1}, {0, -1, 0}};
    case MeshView::kSide:
      return {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}};
    case MeshView::kTop:
      return {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  }
  return {};
}

const char* NameOf(MeshView view) {
  switch (view) {
    case MeshView::kFront:
      return "front";
    case MeshView::kSide:
      return "side";
    case MeshView::kTop:
      return "top";
  }
  return "";
}

struct Projected {
  std::array<Eigen::Vector2f, 3> corners;  // pixels
  float depth = 0;                         // larger: nearer the viewer
  float area = 0;                          // pixels^2
  float facing = 0;                        // |cos| between the face normal and the view
};

}  // namespace

std::string MeshViewSvg(const geometry::Mesh& mesh,
                        const std::vector<std::array<uint8_t, 3>>& face_colours, MeshView view,
                        int size_px) {
  const Axes axes = AxesOf(view);
  Eigen::Vector3f min, max;
  geometry::Bounds(mesh, &min, &max);
  const Eigen::Vector3f centre = (min + max) / 2;
  const float extent = std::max((max - min).maxCoeff(), 1e-6f);
  const float margin = 8;
  const float scale = (size_px - 2 * margin) / extent;
  const float half = size_px / 2.0f;

  std::vector<Projected> faces(mesh.num_faces());
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    Projected& p = faces[f];
    Eigen::Vector3f v[3];
    for (int k = 0; k < 3; ++k) {
      v[k] = mesh.vertices[mesh.faces[f][k]] - centre;
      p.corners[k] = {half + scale * v[k].dot(axes.right), half - scale * v[k].dot(axes.up)};
      p.depth += v[k].dot(axes.towards_viewer) / 3;
    }
    const Eigen::Vector2f a = p.corners[1] - p.corners[0], b = p.corners[2] - p.corners[0];
    p.area = std::fabs(a.x() * b.y() - a.y() * b.x()) / 2;
    const Eigen::Vector3f normal = (v[1] - v[0]).cross(v[2] - v[0]);
    const float length = normal.norm();
    p.facing = length > 0 ? std::fabs(normal.dot(axes.towards_viewer)) / length : 0;
  }
  std::vector<size_t> order;
  for (size_t f = 0; f < faces.size(); ++f) {
    if (faces[f].area > 1e-3f) order.push_back(f);
  }
  if (order.size() > kMaxSvgFaces) {
    // stable_sort with the index as tie-break keeps the choice deterministic.
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t x, size_t y) { return faces[x].area > faces[y].area; });
    order.resize(kMaxSvgFaces);
  }
  std::stable_sort(order.begin(), order.end(), [&](size_t x, size_t y) {
    return faces[x].depth < faces[y].depth || (faces[x].depth == faces[y].depth && x < y);
  });

  std::string svg = fmt::format(
      "<svg class=\"mesh-view\" width=\"{0}\" "
      "height=\"{0}\" viewBox=\"0 0 {0} {0}\" shape-rendering=\"crispEdges\" role=\"img\" "
      "aria-label=\"mesh, {1} view\">\n"
      "<rect width=\"{0}\" height=\"{0}\" fill=\"#ffffff\"/>\n",
      size_px, NameOf(view));
  for (size_t f : order) {
    const Projected& p = faces[f];
    // Shading by how squarely a face is seen gives the flat projection its depth cue.
    const float light = 0.45f + 0.55f * p.facing;
    std::array<uint8_t, 3> rgb = face_colours[f];
    for (uint8_t& c : rgb) c = static_cast<uint8_t>(std::lround(c * light));
    svg +=
        fmt::format("<polygon points=\"{:.1f},{:.1f} {:.1f},{:.1f} {:.1f},{:.1f}\" fill=\"{}\"/>\n",
                    p.corners[0].x(), p.corners[0].y(), p.corners[1].x(), p.corners[1].y(),
                    p.corners[2].x(), p.corners[2].y(), CssColour(rgb));
  }
  svg += fmt::format("<text x=\"6\" y=\"16\" font-size=\"13\" fill=\"#333\">{}</text>\n</svg>\n",
                     NameOf(view));
  return svg;
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
