#include "core/surface/image_growth.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <numbers>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <queue>
#include <set>

#include "core/surface/circumradius.h"
#include "core/surface/delaunay_2d.h"
#include "core/surface/plane_grid.h"

namespace avc::surface {

ImageGrowthStats& ImageGrowthStats::operator+=(const ImageGrowthStats& other) {
  cells_grown += other.cells_grown;
  nodes_plant += other.nodes_plant;
  nodes_background += other.nodes_background;
  nodes_unknown += other.nodes_unknown;
  nodes_other_colour += other.nodes_other_colour;
  nodes_claimed += other.nodes_claimed;
  nodes_grown += other.nodes_grown;
  vertices_added += other.vertices_added;
  return *this;
}

namespace {

// The colour model of the cell's own points (vertices from samples), when they have colours.
std::optional<ColourModel> CellColourModel(const Cell& cell, const ColourModelOptions& options) {
  if (cell.mesh.colors.size() != cell.source_points.size()) return std::nullopt;
  std::vector<Eigen::Matrix<uint8_t, 3, 1>> colours;
  for (size_t v = 0; v < cell.source_points.size(); ++v) {
    if (cell.source_points[v] >= 0) colours.push_back(cell.mesh.colors[v]);
  }
  return ColourModel::Fit(colours, options);
}

// Keeps a grid of a few million nodes at most (a 2000 x 2000 grid is 30 MB of node state).
constexpr size_t kMaxGridNodes = 4'000'000;

// Each node the front reaches, lifted onto the surface and judged once.
class NodeJudge {
 public:
  NodeJudge(const PlaneGrid& grid, const FittedSurface& fit, const ImageEvidence& evidence,
            const ColourModel* colour, const ClaimedElsewhere& claimed_elsewhere,
            ImageGrowthStats* stats)
      : grid_(grid),
        fit_(fit),
        evidence_(evidence),
        colour_(colour),
        claimed_elsewhere_(claimed_elsewhere),
        stats_(stats),
        verdict_(grid.size(), kUnjudged),
        lifted_(grid.size()) {}

  bool Passable(size_t node) {
    if (verdict_[node] == kUnjudged) Judge(node);
    return verdict_[node] == kPass;
  }
  const Eigen::Vector3d& Lifted(size_t node) const { return lifted_[node]; }

 private:
  static constexpr uint8_t kUnjudged = 0, kPass = 1, kStop = 2;

  void Judge(size_t node) {
    const Eigen::Vector3d carried = grid_.Lifted(node);
    const std::optional<Eigen::Vector3f> fitted = fit_.Project(carried.cast<float>());
    lifted_[node] = fitted ? fitted->cast<double>() : carried;
    verdict_[node] = kStop;
    if (claimed_elsewhere_(lifted_[node])) {
      ++stats_->nodes_claimed;
      return;
    }
    switch (evidence_.Judge(lifted_[node], colour_)) {
      case NodeVerdict::kPlant:
        ++stats_->nodes_plant;
        verdict_[node] = kPass;
        return;
      case NodeVerdict::kBackground:
        ++stats_->nodes_background;
        return;
      case NodeVerdict::kUnknown:
        ++stats_->nodes_unknown;
        return;
      case NodeVerdict::kOtherColour:
        ++stats_->nodes_other_colour;
        return;
    }
  }

  const PlaneGrid& grid_;
  const FittedSurface& fit_;
  const ImageEvidence& evidence_;
  const ColourModel* colour_;  // null: the masks alone
  const ClaimedElsewhere& claimed_elsewhere_;
  ImageGrowthStats* stats_;
  std::vector<uint8_t> verdict_;
  std::vector<Eigen::Vector3d> lifted_;
};

// The level set's front: arrival times from the covered nodes at unit speed through passable
// nodes (8-neighbours, Dijkstra; ties in node order), up to reach (m). 1 for the nodes reached.
std::vector<uint8_t> PropagateFront(const PlaneGrid& grid, double reach, NodeJudge& judge) {
  const std::vector<uint8_t>& covered = grid.covered();
  std::vector<double> arrival(grid.size(), std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> front;
  for (size_t node = 0; node < grid.size(); ++node) {
    if (covered[node]) {
      arrival[node] = 0.0;
      front.emplace(0.0, node);
    }
  }
  std::vector<uint8_t> grown(grid.size(), 0);
  while (!front.empty()) {
    const auto [time, node] = front.top();
    front.pop();
    if (time > arrival[node]) continue;
    for (int dr = -1; dr <= 1; ++dr) {
      for (int dc = -1; dc <= 1; ++dc) {
        const int column = grid.Column(node) + dc, row = grid.Row(node) + dr;
        if ((dc == 0 && dr == 0) || column < 0 || row < 0 || column >= grid.width() ||
            row >= grid.height()) {
          continue;
        }
        const size_t next = grid.Node(column, row);
        const double step = grid.pitch() * (dc != 0 && dr != 0 ? std::numbers::sqrt2 : 1.0);
        if (covered[next] || time + step > reach || time + step >= arrival[next]) continue;
        if (!judge.Passable(next)) continue;
        arrival[next] = time + step;
        grown[next] = 1;
        front.emplace(arrival[next], next);
      }
    }
  }
  return grown;
}

// The curvature term: one Merriman-Bence-Osher step on the covered-or-grown indicator, then
// only grown nodes still joined to the cell through grown nodes are kept.
std::vector<uint8_t> SmoothGrownRegion(const PlaneGrid& grid, const std::vector<uint8_t>& grown,
                                       double sigma) {
  const std::vector<uint8_t>& covered = grid.covered();
  cv::Mat indicator(grid.height(), grid.width(), CV_32F);
  for (size_t node = 0; node < grid.size(); ++node) {
    indicator.at<float>(grid.Row(node), grid.Column(node)) = covered[node] || grown[node];
  }
  cv::Mat blurred;
  cv::GaussianBlur(indicator, blurred, cv::Size(0, 0), sigma, sigma, cv::BORDER_CONSTANT);
  std::vector<uint8_t> kept(grid.size(), 0);
  std::deque<size_t> queue;
  for (size_t node = 0; node < grid.size(); ++node) {
    if (covered[node]) queue.push_back(node);
  }
  while (!queue.empty()) {
    const size_t node = queue.front();
    queue.pop_front();
    const int steps[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (const auto& step : steps) {
      const int column = grid.Column(node) + step[0], row = grid.Row(node) + step[1];
      if (column < 0 || row < 0 || column >= grid.width() || row >= grid.height()) continue;
      const size_t next = grid.Node(column, row);
      if (kept[next] || !grown[next] || blurred.at<float>(row, column) < 0.5f) continue;
      kept[next] = 1;
      queue.push_back(next);
    }
  }
  return kept;
}

// The grown nodes that become vertices: a lattice of about one spacing inside, and every
// lattice-parity node of the outline so the outline keeps the grid's precision; none within
// half a spacing of a vertex the cell already has.
std::vector<size_t> NewVertexNodes(const PlaneGrid& grid, const Cell& cell,
                                   const std::vector<uint8_t>& grown, double spacing) {
  const int lattice = std::max(1, static_cast<int>(std::lround(spacing / grid.pitch())));
  std::vector<uint8_t> near_vertex(grid.size(), 0);
  const int radius = static_cast<int>(std::ceil(0.5 * spacing / grid.pitch()));
  for (const Eigen::Vector3f& vertex : cell.mesh.vertices) {
    const size_t centre = grid.NearestNode(cell.plane.Project(vertex));
    for (int dr = -radius; dr <= radius; ++dr) {
      for (int dc = -radius; dc <= radius; ++dc) {
        const int column = grid.Column(centre) + dc, row = grid.Row(centre) + dr;
        if (column < 0 || row < 0 || column >= grid.width() || row >= grid.height()) continue;
        if (dc * dc + dr * dr <= radius * radius) near_vertex[grid.Node(column, row)] = 1;
      }
    }
  }
  const auto inside = [&](int column, int row) {
    if (column < 0 || row < 0 || column >= grid.width() || row >= grid.height()) return false;
    const size_t node = grid.Node(column, row);
    return grid.covered()[node] || grown[node];
  };
  std::vector<size_t> nodes;
  for (size_t node = 0; node < grid.size(); ++node) {
    if (!grown[node] || near_vertex[node]) continue;
    const int column = grid.Column(node), row = grid.Row(node);
    const bool on_lattice = column % lattice == 0 && row % lattice == 0;
    const bool outline = !inside(column + 1, row) || !inside(column - 1, row) ||
                         !inside(column, row + 1) || !inside(column, row - 1);
    if (on_lattice || (outline && (column + row) % lattice == 0)) nodes.push_back(node);
  }
  return nodes;
}

}  // namespace

FittedSurfaceOptions GrownPartFit(const FittedSurfaceOptions& fit,
                                  const ImageGrowthOptions& options) {
  FittedSurfaceOptions grown = fit;
  grown.max_radius_factor = options.max_growth_factor + fit.max_radius_factor;
  return grown;
}

ImageGrowthStats GrowCellWithImages(Cell& cell, const std::vector<Eigen::Vector3f>& samples,
                                    const ImageEvidence& evidence,
                                    const ClaimedElsewhere& claimed_elsewhere, double spacing,
                                    double alpha, const FittedSurfaceOptions& fit,
                                    const ImageGrowthOptions& options) {
  ImageGrowthStats stats;
  geometry::Mesh& mesh = cell.mesh;
  if (mesh.faces.empty() || !(spacing > 0.0)) return stats;
  const double reach = options.max_growth_factor * spacing;
  const PlaneGrid grid(cell, options.grid_factor * spacing, reach + spacing, kMaxGridNodes);

  std::vector<Eigen::Vector3f> own_samples;
  for (int32_t source : cell.source_points) {
    if (source >= 0) own_samples.push_back(samples[source]);
  }
  const FittedSurface surface(std::move(own_samples), cell.plane.normal, spacing,
                              GrownPartFit(fit, options));
  const std::optional<ColourModel> colour =
      options.colour_agreement ? CellColourModel(cell, options.colour) : std::nullopt;
  NodeJudge judge(grid, surface, evidence, colour ? &*colour : nullptr, claimed_elsewhere, &stats);
  const std::vector<uint8_t> grown = SmoothGrownRegion(
      grid, PropagateFront(grid, reach, judge), options.smoothing_factor * spacing / grid.pitch());
  stats.nodes_grown = static_cast<size_t>(std::count(grown.begin(), grown.end(), 1));
  if (stats.nodes_grown == 0) return stats;

  // The cell's vertices and the new ones, triangulated together on the plane.
  const std::vector<size_t> new_nodes = NewVertexNodes(grid, cell, grown, spacing);
  const size_t old_count = mesh.vertices.size();
  std::vector<Eigen::Vector2d> flat;
  std::vector<Eigen::Vector3d> lifted;
  for (const Eigen::Vector3f& vertex : mesh.vertices) {
    flat.push_back(cell.plane.Project(vertex));
    lifted.push_back(vertex.cast<double>());
  }
  for (size_t node : new_nodes) {
    // Where the lift put the node, not its grid centre: the fitted surface moves a node along
    // its local normal, so within the plane too, and neighbours that crossed over each other
    // made faces folded back on the leaf (tests/core/surface/image_growth_test.cc).
    flat.push_back(cell.plane.Project(judge.Lifted(node).cast<float>()));
    lifted.push_back(judge.Lifted(node));
  }
  std::set<std::array<int, 3>> old_faces;
  for (const Eigen::Vector3i& face : mesh.faces) {
    std::array<int, 3> key{face[0], face[1], face[2]};
    std::sort(key.begin(), key.end());
    old_faces.insert(key);
  }
  std::vector<Eigen::Vector3i> faces;
  for (const Eigen::Vector3i& t : Delaunay2d(flat)) {
    std::array<int, 3> key{t[0], t[1], t[2]};
    std::sort(key.begin(), key.end());
    // A face of the cell stays whatever the grid says (slivers may hold no node).
    if (key[2] < static_cast<int>(old_count) && old_faces.count(key) > 0) {
      faces.push_back(t);
      continue;
    }
    const size_t centroid = grid.NearestNode((flat[t[0]] + flat[t[1]] + flat[t[2]]) / 3.0);
    if (!grid.covered()[centroid] && !grown[centroid]) continue;
    if (Circumradius<2>(flat[t[0]], flat[t[1]], flat[t[2]]) > alpha) continue;
    if (Circumradius<3>(lifted[t[0]], lifted[t[1]], lifted[t[2]]) > alpha) continue;
    faces.push_back(t);
  }
  for (size_t node : new_nodes) {
    mesh.vertices.push_back(judge.Lifted(node).cast<float>());
    if (!mesh.colors.empty()) mesh.colors.push_back(mesh.colors[grid.nearest_vertex(node)]);
    cell.source_points.push_back(-1);
  }
  mesh.faces = std::move(faces);
  mesh.face_labels.assign(mesh.faces.size(), cell.cluster);
  stats.vertices_added = new_nodes.size();
  stats.cells_grown = 1;
  return stats;
}

}  // namespace avc::surface
