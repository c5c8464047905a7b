#include "services/planner/patch_visibility.h"

#include <fmt/format.h>
#include <octomap/OcTree.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace avc::planner {
namespace {

// Whether `camera` (centre `eye`) sees a point whose surface normal is `normal` (either side),
// unoccluded up to `stop_short` before it.
bool Sees(const ppr::PlantProxy& proxy, const camera::Camera& camera, const Eigen::Vector3d& eye,
          const Eigen::Vector3d& point, const Eigen::Vector3d& normal, double stop_short,
          double cos_limit) {
  const auto pixel = camera.Project(point);
  if (!pixel) return false;
  const camera::Intrinsics& k = camera.intrinsics;
  if (pixel->x() < 0 || pixel->y() < 0 || pixel->x() > k.width - 1 || pixel->y() > k.height - 1) {
    return false;
  }
  const Eigen::Vector3d to_eye = eye - point;
  const double distance = to_eye.norm();
  if (std::abs(normal.dot(to_eye)) < cos_limit * distance) return false;
  const double range = distance - stop_short;
  if (range <= 0) return true;
  // castRay walks the tree from the eye; unknown space does not block (ignoreUnknown).
  const Eigen::Vector3d direction = -to_eye / distance;
  octomap::point3d hit;
  return !proxy.tree().castRay(
      octomap::point3d(static_cast<float>(eye.x()), static_cast<float>(eye.y()),
                       static_cast<float>(eye.z())),
      octomap::point3d(static_cast<float>(direction.x()), static_cast<float>(direction.y()),
                       static_cast<float>(direction.z())),
      hit, true, range);
}

// Every stride-th face of a patch is tested.
size_t SampleStride(const SurfacePatch& patch, const VisibilityOptions& options) {
  return std::max<size_t>(
      1, (patch.points.size() + options.max_sampled_faces - 1) / options.max_sampled_faces);
}

// Calls seen(bool) for each sampled face of the patch, in order.
template <typename SeenFunction>
void ForSampledFaces(const ppr::PlantProxy& proxy, const SurfacePatch& patch,
                     const camera::Camera& camera, const VisibilityOptions& options,
                     SeenFunction&& seen) {
  // Stop the ray before the face's own voxel: a face on the far side of a one-voxel leaf is the
  // leaf's other side, seen through it.
  const double stop_short = 1.01 * proxy.voxel_size();
  const double cos_limit = std::cos(options.max_grazing_deg * M_PI / 180);
  const Eigen::Vector3d eye = camera.T_cam_world.inverse().translation();
  // An evenly strided sample of at most max_sampled_faces faces estimates the fraction well
  // enough (+-0.1 at 32) and bounds the cost on fine proxies.
  const size_t stride = SampleStride(patch, options);
  for (size_t f = 0; f < patch.points.size(); f += stride) {
    seen(Sees(proxy, camera, eye, patch.points[f], patch.normal, stop_short, cos_limit));
  }
}

}  // namespace

double SeenFraction(const ppr::PlantProxy& proxy, const SurfacePatch& patch,
                    const camera::Camera& camera, const VisibilityOptions& options) {
  size_t seen = 0, tried = 0;
  ForSampledFaces(proxy, patch, camera, options, [&](bool sees) {
    seen += sees;
    ++tried;
  });
  return tried == 0 ? 0 : static_cast<double>(seen) / tried;
}

PatchesSeen FacesSeenBy(const ppr::PlantProxy& proxy, const std::vector<SurfacePatch>& patches,
                        const camera::Camera& camera, const VisibilityOptions& options) {
  PatchesSeen seen;
  for (const SurfacePatch& patch : patches) {
    ForSampledFaces(proxy, patch, camera, options, [&](bool sees) { seen.push_back(sees); });
  }
  return seen;
}

size_t SampledFaceCount(const SurfacePatch& patch, const VisibilityOptions& options) {
  const size_t stride = SampleStride(patch, options);
  return (patch.points.size() + stride - 1) / stride;
}

PatchesSeen PatchesSeenFromFaces(const std::vector<SurfacePatch>& patches, const PatchesSeen& faces,
                                 const VisibilityOptions& options) {
  PatchesSeen seen(patches.size());
  size_t next = 0;
  for (size_t p = 0; p < patches.size(); ++p) {
    const size_t sampled = SampledFaceCount(patches[p], options);
    if (next + sampled > faces.size()) {
      throw std::invalid_argument(fmt::format(
          "patch visibility: {} faces seen for patches that sample more", faces.size()));
    }
    size_t count = 0;
    for (size_t k = 0; k < sampled; ++k) count += faces[next++];
    // As SeenFraction computes it, so both give the same verdict.
    const double fraction = sampled == 0 ? 0 : static_cast<double>(count) / sampled;
    seen[p] = fraction >= options.min_seen_fraction;
  }
  return seen;
}

PatchesSeen PatchesSeenBy(const ppr::PlantProxy& proxy, const std::vector<SurfacePatch>& patches,
                          const camera::Camera& camera, const VisibilityOptions& options) {
  PatchesSeen seen(patches.size());
  for (size_t p = 0; p < patches.size(); ++p) {
    seen[p] = SeenFraction(proxy, patches[p], camera, options) >= options.min_seen_fraction;
  }
  return seen;
}

void AddView(const PatchesSeen& seen, PatchViewCounts* counts) {
  if (counts->size() != seen.size()) counts->assign(seen.size(), 0);
  for (size_t p = 0; p < seen.size(); ++p) (*counts)[p] += seen[p];
}

void RemoveView(const PatchesSeen& seen, PatchViewCounts* counts) {
  for (size_t p = 0; p < seen.size() && p < counts->size(); ++p) (*counts)[p] -= seen[p];
}

std::vector<double> PatchScores(const PatchViewCounts& counts, const VisibilityOptions& options) {
  std::vector<double> scores;
  scores.reserve(counts.size());
  for (const uint16_t n : counts) scores.push_back(static_cast<double>(n) / options.min_views);
  return scores;
}

}  // namespace avc::planner
