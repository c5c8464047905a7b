#include "orchestrator/report_svg.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "orchestrator/report_encode.h"

namespace avc::orchestrator::report {
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

}  // namespace avc::orchestrator::report
