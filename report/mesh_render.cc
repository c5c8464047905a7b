#include "report/mesh_render.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <utility>

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

// Rendered at this many times the output size and averaged down: smooth edges, and faces a
// fraction of an output pixel wide still cover their share of it.
constexpr int kSupersample = 2;

// A depth-buffered canvas: a pixel takes the colour of the nearest face whose triangle holds the
// pixel's centre.
class Canvas {
 public:
  explicit Canvas(int size)
      : image_(size, size, CV_8UC3, cv::Scalar(255, 255, 255)),
        depth_(static_cast<size_t>(size) * size, -std::numeric_limits<float>::infinity()) {}

  // Corners in pixels (x right, y down) with their depth (larger: nearer the viewer).
  void Fill(const std::array<Eigen::Vector2f, 3>& p, const std::array<float, 3>& depth,
            const cv::Vec3b& bgr) {
    const float area = Edge(p[0], p[1], p[2]);
    // Seen edge-on, or so large that its area overflows: nothing to draw.
    if (area == 0 || !std::isfinite(area)) return;
    const int last = image_.cols - 1;
    // The triangle's pixel range, clamped to the canvas before it becomes an int.
    const auto range = [last](float lo, float hi) {
      return std::pair<int, int>(static_cast<int>(std::floor(std::clamp(lo, 0.0f, 1.0f * last))),
                                 static_cast<int>(std::ceil(std::clamp(hi, 0.0f, 1.0f * last))));
    };
    const auto [x0, x1] =
        range(std::min({p[0].x(), p[1].x(), p[2].x()}), std::max({p[0].x(), p[1].x(), p[2].x()}));
    const auto [y0, y1] =
        range(std::min({p[0].y(), p[1].y(), p[2].y()}), std::max({p[0].y(), p[1].y(), p[2].y()}));
    const int size = image_.cols;
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const Eigen::Vector2f centre(x + 0.5f, y + 0.5f);
        // Barycentric weights, positive inside whichever way the corners wind.
        const float w0 = Edge(p[1], p[2], centre) / area;
        const float w1 = Edge(p[2], p[0], centre) / area;
        const float w2 = Edge(p[0], p[1], centre) / area;
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        const float z = w0 * depth[0] + w1 * depth[1] + w2 * depth[2];
        float& nearest = depth_[static_cast<size_t>(y) * size + x];
        if (z <= nearest) continue;
        nearest = z;
        image_.at<cv::Vec3b>(y, x) = bgr;
      }
    }
  }

  const cv::Mat& image() const { return image_; }

 private:
  // Twice the signed area of (a, b, c).
  static float Edge(const Eigen::Vector2f& a, const Eigen::Vector2f& b, const Eigen::Vector2f& c) {
    return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
  }

  cv::Mat image_;
  std::vector<float> depth_;
};

}  // namespace

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

cv::Mat RenderMeshView(const geometry::Mesh& mesh,
                       const std::vector<std::array<uint8_t, 3>>& face_colours, MeshView view,
                       int size_px) {
  const Axes axes = AxesOf(view);
  const int size = size_px * kSupersample;
  Canvas canvas(size);
  if (mesh.num_faces() > 0) {
    // The finite vertices' bounds: one bad vertex must not shrink the picture to a point.
    Eigen::Vector3f min = Eigen::Vector3f::Constant(std::numeric_limits<float>::max());
    Eigen::Vector3f max = -min;
    for (const Eigen::Vector3f& v : mesh.vertices) {
      if (!v.allFinite()) continue;
      min = min.cwiseMin(v);
      max = max.cwiseMax(v);
    }
    if ((min.array() > max.array()).any()) min = max = Eigen::Vector3f::Zero();
    const Eigen::Vector3f centre = (min + max) / 2;
    const float extent = std::max((max - min).maxCoeff(), 1e-6f);
    const float margin = 8.0f * kSupersample;
    const float scale = (size - 2 * margin) / extent;
    const float half = size / 2.0f;
    for (size_t f = 0; f < mesh.num_faces(); ++f) {
      std::array<Eigen::Vector3f, 3> v;
      std::array<Eigen::Vector2f, 3> corners;
      std::array<float, 3> depth;
      for (int k = 0; k < 3; ++k) {
        v[k] = mesh.vertices[mesh.faces[f][k]] - centre;
        corners[k] = {half + scale * v[k].dot(axes.right), half - scale * v[k].dot(axes.up)};
        depth[k] = v[k].dot(axes.towards_viewer);
      }
      if (!(v[0].allFinite() && v[1].allFinite() && v[2].allFinite())) continue;  // a bad corner
      const Eigen::Vector3f normal = (v[1] - v[0]).cross(v[2] - v[0]);
      const float length = normal.norm();
      const float facing = length > 0 ? std::fabs(normal.dot(axes.towards_viewer)) / length : 0;
      // Shading by how squarely a face is seen gives the flat projection its depth cue.
      const float light = 0.45f + 0.55f * facing;
      const std::array<uint8_t, 3>& rgb = face_colours[f];
      const auto shade = [light](uint8_t c) {
        return static_cast<uint8_t>(std::lround(c * light));
      };
      canvas.Fill(corners, depth, cv::Vec3b(shade(rgb[2]), shade(rgb[1]), shade(rgb[0])));
    }
  }
  cv::Mat out;
  cv::resize(canvas.image(), out, cv::Size(size_px, size_px), 0, 0, cv::INTER_AREA);
  return out;
}

}  // namespace avc::report
