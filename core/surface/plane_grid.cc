#include "core/surface/plane_grid.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

namespace avc::surface {

PlaneGrid::PlaneGrid(const Cell& cell, double pitch, double margin, size_t max_nodes)
    : plane_(cell.plane) {
  std::vector<Eigen::Vector2d> flat;
  flat.reserve(cell.mesh.vertices.size());
  Eigen::Vector2d low = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d high = -low;
  for (const Eigen::Vector3f& vertex : cell.mesh.vertices) {
    flat.push_back(plane_.Project(vertex));
    low = low.cwiseMin(flat.back());
    high = high.cwiseMax(flat.back());
  }
  if (flat.empty()) return;
  low.array() -= margin;
  high.array() += margin;
  const Eigen::Vector2d extent = high - low;
  const double nodes = (extent.x() / pitch + 1.0) * (extent.y() / pitch + 1.0);
  if (nodes > static_cast<double>(max_nodes)) pitch *= std::sqrt(nodes / max_nodes);
  pitch_ = pitch;
  origin_ = low;
  width_ = static_cast<int>(std::ceil(extent.x() / pitch)) + 1;
  height_ = static_cast<int>(std::ceil(extent.y() / pitch)) + 1;
  covered_.assign(size(), 0);
  height_above_.assign(size(), 0.0);
  nearest_vertex_.assign(size(), -1);
  Rasterise(cell, flat);
  CarryOutwards();
}

Eigen::Vector2d PlaneGrid::Centre(size_t node) const {
  return origin_ + pitch_ * Eigen::Vector2d(Column(node), Row(node));
}

size_t PlaneGrid::NearestNode(const Eigen::Vector2d& flat) const {
  const Eigen::Vector2d at = (flat - origin_) / pitch_;
  const int column = std::clamp(static_cast<int>(std::lround(at.x())), 0, width_ - 1);
  const int row = std::clamp(static_cast<int>(std::lround(at.y())), 0, height_ - 1);
  return Node(column, row);
}

Eigen::Vector3d PlaneGrid::Lifted(size_t node) const {
  const Eigen::Vector2d c = Centre(node);
  return plane_.origin + c.x() * plane_.u + c.y() * plane_.v + height_above_[node] * plane_.normal;
}

// Every node inside a face gets the face's interpolated height and its nearest corner.
void PlaneGrid::Rasterise(const Cell& cell, const std::vector<Eigen::Vector2d>& flat) {
  for (const Eigen::Vector3i& face : cell.mesh.faces) {
    const Eigen::Vector2d a = flat[face[0]], b = flat[face[1]], c = flat[face[2]];
    const double area = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    if (!(std::abs(area) > 0.0)) continue;
    const Eigen::Vector2d low = (a.cwiseMin(b).cwiseMin(c) - origin_) / pitch_;
    const Eigen::Vector2d high = (a.cwiseMax(b).cwiseMax(c) - origin_) / pitch_;
    double heights[3];
    for (int k = 0; k < 3; ++k) {
      heights[k] = (cell.mesh.vertices[face[k]].cast<double>() - plane_.origin).dot(plane_.normal);
    }
    for (int row = std::max(0, static_cast<int>(std::ceil(low.y())));
         row <= std::min(height_ - 1, static_cast<int>(std::floor(high.y()))); ++row) {
      for (int column = std::max(0, static_cast<int>(std::ceil(low.x())));
           column <= std::min(width_ - 1, static_cast<int>(std::floor(high.x()))); ++column) {
        const size_t node = Node(column, row);
        const Eigen::Vector2d p = Centre(node);
        // Barycentric weights of a, b, c.
        const double wb = ((p - a).x() * (c - a).y() - (p - a).y() * (c - a).x()) / area;
        const double wc = ((b - a).x() * (p - a).y() - (b - a).y() * (p - a).x()) / area;
        const double wa = 1.0 - wb - wc;
        constexpr double kOnEdge = -1e-9;
        if (wa < kOnEdge || wb < kOnEdge || wc < kOnEdge) continue;
        covered_[node] = 1;
        height_above_[node] = wa * heights[0] + wb * heights[1] + wc * heights[2];
        const int corner = wa >= wb && wa >= wc ? 0 : (wb >= wc ? 1 : 2);
        nearest_vertex_[node] = face[corner];
      }
    }
  }
}

// Breadth first from the covered nodes: each other node takes its height and vertex from the
// neighbour that reached it first (in node order among equals), so the result is deterministic.
void PlaneGrid::CarryOutwards() {
  std::deque<size_t> queue;
  for (size_t node = 0; node < size(); ++node) {
    if (covered_[node]) queue.push_back(node);
  }
  while (!queue.empty()) {
    const size_t node = queue.front();
    queue.pop_front();
    const int column = Column(node), row = Row(node);
    const int steps[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (const auto& step : steps) {
      const int c = column + step[0], r = row + step[1];
      if (c < 0 || r < 0 || c >= width_ || r >= height_) continue;
      const size_t next = Node(c, r);
      if (nearest_vertex_[next] >= 0) continue;
      nearest_vertex_[next] = nearest_vertex_[node];
      height_above_[next] = height_above_[node];
      queue.push_back(next);
    }
  }
}

}  // namespace avc::surface
