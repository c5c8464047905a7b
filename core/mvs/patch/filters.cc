#include "core/mvs/patch/filters.h"

#include <tbb/parallel_for.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <numeric>

namespace avc::mvs::patch {
namespace {

// Metres per reference pixel at the patch.
double Footprint(const Patch& p, const std::vector<PatchImage>& images) {
  const PatchImage& ref = images[p.reference];
  return ref.Depth(p.centre) / ref.fx();
}

// Close to each other's planes (PMVS isNeighbor): within two cells' footprints of p.
bool AreNeighbours(const Patch& p, const Patch& q, double rho) {
  const Eigen::Vector3d d = q.centre - p.centre;
  return std::abs(d.dot(p.normal)) + std::abs(d.dot(q.normal)) < 2 * rho;
}

double Support(const Patch& p) { return static_cast<double>(p.visible.size()) * p.score; }

template <class Decide>
size_t RemoveWhere(PatchSet* set, const Decide& decide) {
  const std::vector<uint32_t> ids = set->AliveIds();
  std::vector<uint8_t> remove(ids.size(), 0);
  tbb::parallel_for(size_t{0}, ids.size(), [&](size_t k) { remove[k] = decide(ids[k]) ? 1 : 0; });
  size_t removed = 0;
  for (size_t k = 0; k < ids.size(); ++k) {
    if (remove[k]) set->alive[ids[k]] = 0, ++removed;
  }
  return removed;
}

}  // namespace

size_t FilterOutside(const std::vector<PatchImage>& images, const PatchMvsOptions& options,
                     PatchSet* set, CellGrids* grids) {
  const size_t removed = RemoveWhere(set, [&](uint32_t id) {
    const Patch& p = set->patches[id];
    const double rho = options.cell_size * Footprint(p, images);
    double behind = 0;
    for (uint32_t j : p.visible) {
      int cx = 0, cy = 0;
      double depth = 0;
      if (!grids->CellOfPoint(j, images[j], p.centre, &cx, &cy, &depth)) continue;
      const double tolerance =
          grids->OcclusionTolerance(options.occlusion_cells, depth, images[j].fx());
      for (uint32_t q : grids->Patches(j, cx, cy)) {
        const Patch& other = set->patches[q];
        if (q == id || images[j].Depth(other.centre) <= depth + tolerance) continue;
        if (!AreNeighbours(p, other, rho)) behind += Support(other);
      }
    }
    return Support(p) < behind;
  });
  grids->Rebuild(set->patches, set->alive, images);
  return removed;
}

size_t FilterExact(const std::vector<PatchImage>& images, const PatchMvsOptions& options,
                   PatchSet* set, CellGrids* grids) {
  const std::vector<uint32_t> ids = set->AliveIds();
  std::vector<std::vector<uint32_t>> kept(ids.size());
  tbb::parallel_for(size_t{0}, ids.size(), [&](size_t k) {
    const Patch& p = set->patches[ids[k]];
    const double rho = options.cell_size * Footprint(p, images);
    for (uint32_t j : p.visible) {
      int cx = 0, cy = 0;
      double depth = 0;
      bool hidden = false;
      if (grids->CellOfPoint(j, images[j], p.centre, &cx, &cy, &depth)) {
        const double tolerance =
            grids->OcclusionTolerance(options.occlusion_cells, depth, images[j].fx());
        for (uint32_t q : grids->Patches(j, cx, cy)) {
          const Patch& other = set->patches[q];
          if (q != ids[k] && images[j].Depth(other.centre) < depth - tolerance &&
              !AreNeighbours(p, other, rho)) {
            hidden = true;
            break;
          }
        }
      }
      if (!hidden) kept[k].push_back(j);
    }
  });
  size_t removed = 0;
  for (size_t k = 0; k < ids.size(); ++k) {
    Patch& p = set->patches[ids[k]];
    const bool has_reference = std::binary_search(kept[k].begin(), kept[k].end(), p.reference);
    if (!has_reference || static_cast<int>(kept[k].size()) < options.min_images) {
      set->alive[ids[k]] = 0;
      ++removed;
    } else {
      p.visible = std::move(kept[k]);
    }
  }
  grids->Rebuild(set->patches, set->alive, images);
  return removed;
}

size_t FilterRegularity(const std::vector<PatchImage>& images, const PatchMvsOptions& options,
                        PatchSet* set, CellGrids* grids) {
  constexpr int kRadius = 2;         // cells around the patch in its reference image
  constexpr int kMinNeighbours = 4;  // fewer: no plane to compare with
  const size_t removed = RemoveWhere(set, [&](uint32_t id) {
    const Patch& p = set->patches[id];
    const uint32_t r = p.reference;
    int cx = 0, cy = 0;
    if (!grids->CellOfPoint(r, images[r], p.centre, &cx, &cy)) return false;
    const double footprint = Footprint(p, images);
    const double reach = 2.0 * (kRadius + 1) * options.cell_size * footprint;
    std::vector<Eigen::Vector3d> near;
    for (int y = std::max(0, cy - kRadius); y <= std::min(grids->rows(r) - 1, cy + kRadius); ++y) {
      for (int x = std::max(0, cx - kRadius); x <= std::min(grids->cols(r) - 1, cx + kRadius);
           ++x) {
        for (uint32_t q : grids->Patches(r, x, y)) {
          const Patch& other = set->patches[q];
          if (q == id || (other.centre - p.centre).norm() > reach) continue;
          if (other.normal.dot(p.normal) < 0.5) continue;  // other side of a thin leaf
          near.push_back(other.centre);
        }
      }
    }
    if (static_cast<int>(near.size()) < kMinNeighbours) return false;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& c : near) mean += c;
    mean /= static_cast<double>(near.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (const auto& c : near) covariance += (c - mean) * (c - mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
    const Eigen::Vector3d plane_normal = solver.eigenvectors().col(0);
    return std::abs(plane_normal.dot(p.centre - mean)) > options.regularity_threshold * footprint;
  });
  grids->Rebuild(set->patches, set->alive, images);
  return removed;
}

size_t FilterSmallGroups(const std::vector<PatchImage>& images, const PatchMvsOptions& options,
                         PatchSet* set, CellGrids* grids) {
  const std::vector<uint32_t> ids = set->AliveIds();
  std::vector<std::vector<uint32_t>> edges(ids.size());
  tbb::parallel_for(size_t{0}, ids.size(), [&](size_t k) {
    const Patch& p = set->patches[ids[k]];
    const double rho = options.cell_size * Footprint(p, images);
    for (uint32_t j : p.visible) {
      int cx = 0, cy = 0;
      if (!grids->CellOfPoint(j, images[j], p.centre, &cx, &cy)) continue;
      for (int y = std::max(0, cy - 1); y <= std::min(grids->rows(j) - 1, cy + 1); ++y) {
        for (int x = std::max(0, cx - 1); x <= std::min(grids->cols(j) - 1, cx + 1); ++x) {
          for (uint32_t q : grids->Patches(j, x, y)) {
            if (q > ids[k] && AreNeighbours(p, set->patches[q], rho)) edges[k].push_back(q);
          }
        }
      }
    }
  });
  std::vector<uint32_t> parent(set->patches.size());
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (size_t k = 0; k < ids.size(); ++k) {
    for (uint32_t q : edges[k]) {
      const uint32_t a = find(ids[k]), b = find(q);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  }
  std::vector<uint32_t> size(set->patches.size(), 0);
  for (uint32_t id : ids) ++size[find(id)];
  size_t removed = 0;
  for (uint32_t id : ids) {
    if (static_cast<int>(size[find(id)]) < options.min_group_size) {
      set->alive[id] = 0;
      ++removed;
    }
  }
  grids->Rebuild(set->patches, set->alive, images);
  return removed;
}

}  // namespace avc::mvs::patch
