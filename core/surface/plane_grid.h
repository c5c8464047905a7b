#pragma once

// A square grid over a cell's plane (Phase 2 with images): the cell's mesh drawn onto it, so
// each node knows whether the cell covers it, the surface's height above the plane there and
// the nearest mesh vertex; nodes outside get the height and vertex of the nearest covered node
// (the surface carried outwards flat, for the fitted surface to bend).

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/surface/cell.h"

namespace avc::surface {

class PlaneGrid {
 public:
  // A grid of the given pitch (m) over the cell's projected vertices, margin (m) beyond them on
  // every side; the pitch grows when that would exceed max_nodes.
  PlaneGrid(const Cell& cell, double pitch, double margin, size_t max_nodes);

  int width() const { return width_; }
  int height() const { return height_; }
  size_t size() const { return static_cast<size_t>(width_) * height_; }
  double pitch() const { return pitch_; }
  int Column(size_t node) const { return static_cast<int>(node % width_); }
  int Row(size_t node) const { return static_cast<int>(node / width_); }
  size_t Node(int column, int row) const { return static_cast<size_t>(row) * width_ + column; }

  // Plane coordinates of a node, and the node nearest plane coordinates (clamped to the grid).
  Eigen::Vector2d Centre(size_t node) const;
  size_t NearestNode(const Eigen::Vector2d& flat) const;

  // The node on the surface as the mesh has it: its plane point lifted by its height.
  Eigen::Vector3d Lifted(size_t node) const;

  const std::vector<uint8_t>& covered() const { return covered_; }  // 1 under a mesh face
  int32_t nearest_vertex(size_t node) const { return nearest_vertex_[node]; }

 private:
  void Rasterise(const Cell& cell, const std::vector<Eigen::Vector2d>& flat);
  void CarryOutwards();

  PlaneFrame plane_;
  Eigen::Vector2d origin_;  // plane coordinates of node (0, 0)
  double pitch_ = 0;
  int width_ = 0;
  int height_ = 0;
  std::vector<uint8_t> covered_;
  std::vector<double> height_above_;     // per node (m along plane_.normal)
  std::vector<int32_t> nearest_vertex_;  // per node, -1 where nothing was carried
};

}  // namespace avc::surface
