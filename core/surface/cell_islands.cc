#include "core/surface/cell_islands.h"

#include <utility>

#include "core/surface/mesh_topology.h"

namespace avc::surface {

std::vector<Cell> SplitCellsIntoPieces(std::vector<Cell> cells, size_t* islands) {
  *islands = 0;
  std::vector<Cell> pieces;
  pieces.reserve(cells.size());
  for (Cell& cell : cells) {
    int count = 0;
    const std::vector<int> component = FaceComponents(cell.mesh, &count);
    if (count <= 1) {
      pieces.push_back(std::move(cell));
      continue;
    }
    *islands += static_cast<size_t>(count - 1);
    for (int c = 0; c < count; ++c) {
      Cell piece;
      piece.cluster = cell.cluster;
      piece.plane = cell.plane;
      piece.mesh = cell.mesh;
      std::vector<bool> keep(component.size());
      for (size_t f = 0; f < component.size(); ++f) keep[f] = component[f] == c;
      KeepFaces(piece.mesh, keep);
      for (int old : RemoveUnusedVertices(piece.mesh)) {
        const bool known = static_cast<size_t>(old) < cell.source_points.size();
        piece.source_points.push_back(known ? cell.source_points[old] : -1);
      }
      pieces.push_back(std::move(piece));
    }
  }
  return pieces;
}

}  // namespace avc::surface
