#include "core/surface/laplacian_smoothing.h"

#include <vector>

#include "core/surface/mesh_topology.h"

namespace avc::surface {
namespace {

// Taubin's filter passes frequencies k < 1 / lambda + 1 / mu (0.113 for 0.5 | -0.53) unchanged;
// a loop's lowest mode, its overall size, has k = 1 - cos(2 pi / n), below that from n = 14
// on. Shorter loops would shrink as a whole, so they keep their shape.
constexpr size_t kMinSmoothedLoop = 14;

// One umbrella step of every movable vertex towards the mean of its neighbours, by factor
// (Jacobi order: all moves from the same old positions, so the result does not depend on order).
void UmbrellaStep(geometry::Mesh& mesh, const std::vector<std::vector<int>>& neighbours,
                  double factor) {
  const std::vector<Eigen::Vector3f> old = mesh.vertices;
  for (size_t i = 0; i < neighbours.size(); ++i) {
    if (neighbours[i].empty()) continue;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (int j : neighbours[i]) mean += old[j].cast<double>();
    mean /= static_cast<double>(neighbours[i].size());
    const Eigen::Vector3d p = old[i].cast<double>();
    mesh.vertices[i] = (p + factor * (mean - p)).cast<float>();
  }
}

void Taubin(geometry::Mesh& mesh, const std::vector<std::vector<int>>& neighbours,
            const SmoothingOptions& options) {
  for (int it = 0; it < options.iterations; ++it) {
    UmbrellaStep(mesh, neighbours, options.lambda);
    UmbrellaStep(mesh, neighbours, options.mu);
  }
}

}  // namespace

void SmoothInterior(geometry::Mesh& mesh, const SmoothingOptions& options) {
  std::vector<std::vector<int>> neighbours = VertexNeighbours(mesh);
  const std::vector<bool> boundary = BoundaryVertices(mesh);
  for (size_t i = 0; i < neighbours.size(); ++i) {
    if (boundary[i]) neighbours[i].clear();  // held still
  }
  Taubin(mesh, neighbours, options);
}

void SmoothBoundary(geometry::Mesh& mesh, const SmoothingOptions& options) {
  std::vector<std::vector<int>> neighbours(mesh.vertices.size());
  std::vector<int> loops_through(mesh.vertices.size(), 0);
  for (const BoundaryLoop& loop : BoundaryLoops(mesh)) {
    const size_t n = loop.vertices.size();
    if (!loop.closed || n < kMinSmoothedLoop) continue;
    for (size_t i = 0; i < n; ++i) {
      const int v = loop.vertices[i];
      ++loops_through[v];
      neighbours[v] = {loop.vertices[(i + n - 1) % n], loop.vertices[(i + 1) % n]};
    }
  }
  // A vertex where two loops touch has no single outline to follow: held still.
  for (size_t i = 0; i < neighbours.size(); ++i) {
    if (loops_through[i] != 1) neighbours[i].clear();
  }
  Taubin(mesh, neighbours, options);
}

void SmoothSheet(geometry::Mesh& mesh, const SmoothingOptions& options) {
  SmoothInterior(mesh, options);
  SmoothBoundary(mesh, options);
}

}  // namespace avc::surface
