#include "core/mvs/patch/expansion.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

#include "core/mvs/patch/patch_refiner.h"

namespace avc::mvs::patch {
namespace {

struct Candidate {
  Patch patch;
  uint32_t image;  // the image whose empty cell it fills
  int cx, cy;
  bool ok;  // false: the attempt failed (counted so the cell is not retried forever)
};

// A cell that failed this many expansion attempts is given up.
constexpr uint8_t kMaxAttempts = 3;

std::vector<Candidate> CandidatesFrom(const Patch& source, const std::vector<PatchImage>& images,
                                      const CellGrids& grids, const PatchRefiner& refiner,
                                      const std::vector<std::vector<uint8_t>>& failures) {
  std::vector<Candidate> out;
  std::vector<std::tuple<uint32_t, int, int>> tried;
  const int beta = grids.cell_size();
  constexpr std::array<std::array<int, 2>, 4> kSteps = {{{1, 0}, {-1, 0}, {0, 1}, {0, -1}}};
  for (uint32_t j : source.visible) {
    const PatchImage& image = images[j];
    const Eigen::Vector3d h = image.ProjectH(source.centre);
    int cx = 0, cy = 0;
    if (h.z() <= 0 || !grids.CellOf(j, h.x() / h.z(), h.y() / h.z(), &cx, &cy)) continue;
    for (const auto& step : kSteps) {
      const int nx = cx + step[0], ny = cy + step[1];
      if (nx < 0 || ny < 0 || nx >= grids.cols(j) || ny >= grids.rows(j)) continue;
      if (!grids.Empty(j, nx, ny)) continue;
      if (failures[j][static_cast<size_t>(ny) * grids.cols(j) + nx] >= kMaxAttempts) continue;
      if (std::find(tried.begin(), tried.end(), std::make_tuple(j, nx, ny)) != tried.end()) {
        continue;
      }
      tried.emplace_back(j, nx, ny);
      const double u = nx * beta + 0.5 * (beta - 1), v = ny * beta + 0.5 * (beta - 1);
      if (!image.Usable(u, v)) continue;
      const Eigen::Vector3d ray = image.Ray(u, v);
      const double facing = ray.dot(source.normal);
      if (std::abs(facing) < 0.1) continue;  // grazing: the plane point is ill defined
      const double t = source.normal.dot(source.centre - image.centre()) / facing;
      if (t <= 0) continue;
      Candidate c{source, j, nx, ny, false};
      c.patch.centre = image.centre() + t * ray;
      c.patch.visible.clear();
      // Kept only when it is seen in image j and still fills the cell it was made for.
      c.ok = refiner.Refine(&c.patch) &&
             std::binary_search(c.patch.visible.begin(), c.patch.visible.end(), j);
      if (c.ok) {
        int jx = 0, jy = 0;
        c.ok = grids.CellOfPoint(j, image, c.patch.centre, &jx, &jy) && jx == nx && jy == ny;
      }
      if (!c.ok) {
        c.patch = Patch{};
        out.push_back(std::move(c));
        continue;
      }
      // Cells the new patch covers need no second candidate from this source.
      for (uint32_t k : c.patch.visible) {
        int kx = 0, ky = 0;
        if (grids.CellOfPoint(k, images[k], c.patch.centre, &kx, &ky)) {
          tried.emplace_back(k, kx, ky);
        }
      }
      out.push_back(std::move(c));
    }
  }
  return out;
}

}  // namespace

size_t Expand(const std::vector<uint32_t>& start, const std::vector<PatchImage>& images,
              const OccupancyLookup& lookup, const PatchMvsOptions& options, PatchSet* set,
              CellGrids* grids, const MvsProgress& progress) {
  const PatchRefiner refiner(images, *grids, lookup, options);
  std::vector<std::vector<uint8_t>> failures(images.size());
  for (size_t j = 0; j < images.size(); ++j) {
    failures[j].assign(static_cast<size_t>(grids->cols(j)) * grids->rows(j), 0);
  }
  std::vector<uint32_t> wave = start;
  size_t added = 0;
  while (!wave.empty()) {
    std::vector<std::vector<Candidate>> found(wave.size());
    tbb::parallel_for(size_t{0}, wave.size(), [&](size_t k) {
      found[k] = CandidatesFrom(set->patches[wave[k]], images, *grids, refiner, failures);
    });
    std::vector<uint32_t> next;
    for (auto& candidates : found) {
      for (Candidate& c : candidates) {
        if (!c.ok) {
          uint8_t& count =
              failures[c.image][static_cast<size_t>(c.cy) * grids->cols(c.image) + c.cx];
          if (count < kMaxAttempts) ++count;
          continue;
        }
        if (!grids->Empty(c.image, c.cx, c.cy)) continue;
        const uint32_t id = set->Add(std::move(c.patch));
        grids->Add(id, set->patches[id], images);
        next.push_back(id);
      }
    }
    added += next.size();
    if (progress) progress("expand", added, set->patches.size());
    wave = std::move(next);
  }
  return added;
}

}  // namespace avc::mvs::patch
