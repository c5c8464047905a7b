#include "core/mvs/patch/seeds.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace avc::mvs::patch {
namespace {

// Midpoint of the shortest segment between two rays (origin, unit direction); false when
// they are nearly parallel.
bool Triangulate(const Eigen::Vector3d& o1, const Eigen::Vector3d& d1, const Eigen::Vector3d& o2,
                 const Eigen::Vector3d& d2, Eigen::Vector3d* point) {
  const double b = d1.dot(d2);
  const double denom = 1 - b * b;
  if (denom < 1e-8) return false;
  const Eigen::Vector3d w = o1 - o2;
  const double d = d1.dot(w), e = d2.dot(w);
  const double s = (b * e - d) / denom;
  const double t = (e - b * d) / denom;
  *point = 0.5 * ((o1 + s * d1) + (o2 + t * d2));
  return true;
}

}  // namespace

SeedFinder::SeedFinder(const std::vector<PatchImage>& images,
                       const std::vector<std::vector<Feature>>& features,
                       const std::vector<std::vector<uint32_t>>& neighbours,
                       const std::vector<std::pair<double, double>>& fallback_depths,
                       const PatchMvsOptions& options)
    : images_(images),
      features_(features),
      neighbours_(neighbours),
      fallback_depths_(fallback_depths),
      options_(options) {
  buckets_.resize(images.size());
  for (size_t i = 0; i < images.size(); ++i) {
    Buckets& b = buckets_[i];
    b.cols = (images[i].width() + kBucket - 1) / kBucket;
    b.rows = (images[i].height() + kBucket - 1) / kBucket;
    b.ids.resize(static_cast<size_t>(b.cols) * b.rows);
    for (uint32_t f = 0; f < features[i].size(); ++f) {
      const int bx = std::clamp(static_cast<int>(features[i][f].u) / kBucket, 0, b.cols - 1);
      const int by = std::clamp(static_cast<int>(features[i][f].v) / kBucket, 0, b.rows - 1);
      b.ids[static_cast<size_t>(by) * b.cols + bx].push_back(f);
    }
  }
}

std::optional<Patch> SeedFinder::FromFeature(uint32_t i, const Feature& feature,
                                             const PatchRefiner& refiner) const {
  const PatchImage& image = images_[i];
  double near = fallback_depths_[i].first, far = fallback_depths_[i].second;
  if (image.HasDepthRange()) {
    const auto [n, f] = image.DepthRange(feature.u, feature.v);
    if (f <= 0) return std::nullopt;
    near = n, far = f;
  }
  const Eigen::Vector3d origin = image.centre();
  const Eigen::Vector3d ray = image.Ray(feature.u, feature.v);
  // Depth is along the optical axis; distance along the ray is depth / cos.
  const double cos_axis = ray.dot(image.camera().Axis());
  if (cos_axis <= 1e-6) return std::nullopt;
  const Eigen::Vector3d p_near = origin + ray * (near / cos_axis);
  const Eigen::Vector3d p_far = origin + ray * (far / cos_axis);

  struct Candidate {
    double distance;
    Eigen::Vector3d point;
  };
  std::vector<Candidate> candidates;
  const double max_distance = options_.epipolar_distance;
  for (uint32_t j : neighbours_[i]) {
    const PatchImage& other = images_[j];
    const Eigen::Vector3d h0 = other.ProjectH(p_near), h1 = other.ProjectH(p_far);
    if (h0.z() <= 0 || h1.z() <= 0) continue;
    const Eigen::Vector2d a(h0.x() / h0.z(), h0.y() / h0.z());
    const Eigen::Vector2d b(h1.x() / h1.z(), h1.y() / h1.z());
    const Eigen::Vector2d seg = b - a;
    const double length = seg.norm();
    const Eigen::Vector2d dir =
        length > 1e-9 ? Eigen::Vector2d(seg / length) : Eigen::Vector2d(1, 0);
    // Buckets along the segment (and one either side), each visited once.
    const Buckets& bk = buckets_[j];
    std::vector<uint32_t> cells;
    const int steps = static_cast<int>(std::ceil(length / (kBucket * 0.5))) + 1;
    for (int s = 0; s <= steps; ++s) {
      const Eigen::Vector2d p = a + seg * (static_cast<double>(s) / steps);
      const int bx = static_cast<int>(std::floor(p.x() / kBucket));
      const int by = static_cast<int>(std::floor(p.y() / kBucket));
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int x = bx + dx, y = by + dy;
          if (x < 0 || y < 0 || x >= bk.cols || y >= bk.rows) continue;
          cells.push_back(static_cast<uint32_t>(y * bk.cols + x));
        }
      }
    }
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    for (uint32_t cell : cells) {
      for (uint32_t g : bk.ids[cell]) {
        const Feature& match = features_[j][g];
        if (match.type != feature.type) continue;
        const Eigen::Vector2d q(match.u, match.v);
        const Eigen::Vector2d aq = q - a;
        const double along = aq.dot(dir);
        const double across = std::abs(aq.x() * dir.y() - aq.y() * dir.x());
        if (across > max_distance || along < -max_distance || along > length + max_distance) {
          continue;
        }
        Eigen::Vector3d point;
        if (!Triangulate(origin, ray, other.centre(), other.Ray(match.u, match.v), &point)) {
          continue;
        }
        const double depth = image.Depth(point);
        if (depth < near || depth > far || other.Depth(point) <= 0) continue;
        candidates.push_back({(point - origin).norm(), point});
      }
    }
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& x, const Candidate& y) { return x.distance < y.distance; });
  if (static_cast<int>(candidates.size()) > options_.max_seed_candidates) {
    candidates.resize(options_.max_seed_candidates);
  }
  for (const Candidate& c : candidates) {
    Patch patch;
    patch.centre = c.point;
    patch.normal = (origin - c.point).normalized();
    patch.reference = i;
    if (refiner.Refine(&patch)) return patch;
  }
  return std::nullopt;
}

}  // namespace avc::mvs::patch
