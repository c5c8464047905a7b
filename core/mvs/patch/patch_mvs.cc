#include "core/mvs/patch/patch_mvs.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <stdexcept>

#include "core/dataset/view_transforms.h"
#include "core/mvs/depth_range.h"
#include "core/mvs/occupancy_lookup.h"
#include "core/mvs/patch/cell_grid.h"
#include "core/mvs/patch/expansion.h"
#include "core/mvs/patch/features.h"
#include "core/mvs/patch/filters.h"
#include "core/mvs/patch/patch_refiner.h"
#include "core/mvs/patch/seeds.h"
#include "core/mvs/view_neighbours.h"
#include "core/util/validation.h"

namespace avc::mvs {
namespace {

using patch::CellGrids;
using patch::Feature;
using patch::Patch;
using patch::PatchImage;
using patch::PatchSet;

void Require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

void ValidateViews(const std::vector<dataset::View>& views) {
  Require(views.size() >= 2,
          fmt::format("RunPatchMvs: needs at least 2 views, got {}", views.size()));
  for (size_t i = 0; i < views.size(); ++i) {
    const dataset::View& v = views[i];
    const std::string where = fmt::format("RunPatchMvs: view {} ('{}')", i, v.name);
    Require(!v.image.empty(), where + ": image is empty");
    Require(v.image.type() == CV_8UC3, where + ": image must be CV_8UC3 (BGR)");
    const auto& k = v.camera.intrinsics;
    const std::string bad = k.Validate();
    Require(bad.empty(), where + ": camera intrinsics: " + bad);
    Require(k.width == v.image.cols && k.height == v.image.rows,
            fmt::format("{}: image is {}x{} but the camera is {}x{}", where, v.image.cols,
                        v.image.rows, k.width, k.height));
    Require(!k.HasDistortion(),
            where + ": camera has lens distortion; undistort the views first (dataset::Undistort)");
    Require(v.camera.T_cam_world.matrix().allFinite(), where + ": camera pose is not finite");
    if (!v.mask.empty()) {
      Require(v.mask.type() == CV_8UC1 && v.mask.size() == v.image.size(),
              where + ": mask must be empty or CV_8UC1 of the image size");
      Require(cv::countNonZero(v.mask) > 0, where + ": mask has no plant pixel");
    }
  }
}

int LongestSide(const std::vector<dataset::View>& views) {
  int longest = 0;
  for (const auto& v : views) longest = std::max({longest, v.image.cols, v.image.rows});
  return longest;
}

int AutomaticLevel(const std::vector<dataset::View>& views) {
  const int longest = LongestSide(views);
  int level = 0;
  while ((longest >> level) > 1600) ++level;
  return level;
}

std::vector<PatchImage> PrepareImages(const std::vector<dataset::View>& views, int level,
                                      const MvsBounds& bounds) {
  std::vector<std::unique_ptr<PatchImage>> made(views.size());
  tbb::parallel_for(size_t{0}, views.size(), [&](size_t i) {
    const dataset::View v = dataset::AtPyramidLevel(views[i], level);
    cv::Mat usable =
        v.mask.empty() ? cv::Mat(v.image.size(), CV_8UC1, cv::Scalar(255)) : (v.mask > 0);
    cv::Mat near, far;
    if (!bounds.empty()) {
      const DepthRange range = ComputeDepthRange(v.camera, bounds, bounds.voxel_size);
      cv::Mat covered = range.far_depth > 0;
      cv::bitwise_and(usable, covered, usable);
      near = range.near_depth;
      far = range.far_depth;
    }
    made[i] = std::make_unique<PatchImage>(v.camera, v.image, usable, near, far);
  });
  std::vector<PatchImage> images;
  images.reserve(views.size());
  for (auto& m : made) images.push_back(std::move(*m));
  return images;
}

// Where no proxy bounds the search: half to one and a half times the depth of the point the
// cameras look at.
std::vector<std::pair<double, double>> FallbackDepths(const std::vector<PatchImage>& images,
                                                      const Eigen::Vector3d& scene_centre) {
  std::vector<std::pair<double, double>> depths;
  for (const auto& image : images) {
    const double d = std::max(1e-3, image.Depth(scene_centre));
    depths.push_back({0.5 * d, 1.5 * d});
  }
  return depths;
}

MvsPoints ToPoints(const PatchSet& set, const std::vector<PatchImage>& images) {
  MvsPoints points;
  for (uint32_t id : set.AliveIds()) {
    const Patch& p = set.patches[id];
    Eigen::Vector3d colour = Eigen::Vector3d::Zero();
    int samples = 0;
    for (uint32_t j : p.visible) {
      const Eigen::Vector3d h = images[j].ProjectH(p.centre);
      const double u = h.x() / h.z(), v = h.y() / h.z();
      if (!images[j].Inside(u, v, 0)) continue;
      float rgb[3];
      images[j].Sample(static_cast<float>(u), static_cast<float>(v), rgb);
      colour += Eigen::Vector3d(rgb[0], rgb[1], rgb[2]);
      ++samples;
    }
    if (samples > 0) colour /= samples;
    points.cloud.positions.push_back(p.centre.cast<float>());
    points.cloud.normals.push_back(p.normal.normalized().cast<float>());
    points.cloud.colors.push_back(colour.array().round().min(255).max(0).cast<uint8_t>().matrix());
    points.confidence.push_back(std::clamp(p.score, 0.f, 1.f));
    points.views.push_back(p.visible);
  }
  return points;
}

}  // namespace

std::string PatchMvsOptions::Validate() const {
  FirstProblem problem;
  auto require = [&problem](bool ok, const char* field, const std::string& why) {
    problem.Require(ok, fmt::format("PatchMvsOptions.{}: {}", field, why));
  };
  require(level >= -1 && level <= 6, "level", "must be -1 (automatic) or 0..6");
  require(cell_size >= 1 && cell_size <= 64, "cell_size", "must be 1..64 pixels");
  require(window >= 3 && window <= 21 && window % 2 == 1, "window", "must be odd, 3..21");
  require(std::isfinite(ncc_threshold) && ncc_threshold > -1 && ncc_threshold < 1, "ncc_threshold",
          "must be in (-1, 1)");
  require(std::isfinite(ncc_threshold_before) && ncc_threshold_before > -1 &&
              ncc_threshold_before <= ncc_threshold,
          "ncc_threshold_before", "must be in (-1, ncc_threshold]");
  require(min_images == 0 || min_images >= 2, "min_images", "must be 0 (automatic) or at least 2");
  require(std::isfinite(max_view_angle) && max_view_angle > 0 && max_view_angle < M_PI / 2,
          "max_view_angle", "must be in (0, pi/2)");
  require(features_per_block >= 1, "features_per_block", "must be at least 1");
  require(feature_block >= 4, "feature_block", "must be at least 4 pixels");
  require(std::isfinite(epipolar_distance) && epipolar_distance > 0, "epipolar_distance",
          "must be positive");
  require(max_seed_candidates >= 1, "max_seed_candidates", "must be at least 1");
  require(seed_neighbours >= 1, "seed_neighbours", "must be at least 1");
  require(rounds >= 0, "rounds", "must not be negative");
  require(max_iterations >= 1, "max_iterations", "must be at least 1");
  require(max_refine_images >= 1, "max_refine_images", "must be at least 1");
  require(std::isfinite(min_texture) && min_texture >= 0, "min_texture", "must be >= 0");
  require(std::isfinite(occlusion_cells) && occlusion_cells > 0, "occlusion_cells",
          "must be positive");
  require(std::isfinite(regularity_threshold) && regularity_threshold > 0, "regularity_threshold",
          "must be positive");
  require(min_group_size >= 1, "min_group_size", "must be at least 1");
  require(bounds_dilation >= 0, "bounds_dilation", "must not be negative");
  require(whole_patch_in_mask >= -1 && whole_patch_in_mask <= 1, "whole_patch_in_mask",
          "must be -1 (automatic), 0 or 1");
  return problem.text();
}

MvsPoints RunPatchMvs(const std::vector<dataset::View>& views, const MvsBounds& bounds,
                      const PatchMvsOptions& requested, const MvsProgress& progress) {
  RequireValid(requested);
  ValidateViews(views);
  Require(bounds.empty() || (std::isfinite(bounds.voxel_size) && bounds.voxel_size > 0),
          "RunPatchMvs: bounds.voxel_size must be positive when bounds has voxels");
  for (size_t i = 0; i < bounds.occupied_centres.size(); ++i) {
    Require(bounds.occupied_centres[i].allFinite(),
            fmt::format("RunPatchMvs: bounds.occupied_centres[{}] is not finite", i));
  }
  // The automatic choices made for these views.
  PatchMvsOptions options = requested;
  const int level = options.level < 0 ? AutomaticLevel(views) : options.level;
  options.level = level;
  if (options.min_images == 0) options.min_images = views.size() >= 24 ? 4 : 3;
  if (options.whole_patch_in_mask < 0) {
    options.whole_patch_in_mask = (LongestSide(views) >> level) >= 1000 ? 1 : 0;
  }
  const std::vector<PatchImage> images = PrepareImages(views, level, bounds);
  const OccupancyLookup lookup(bounds);

  // Features and seeding neighbours.
  std::vector<std::vector<Feature>> features(images.size());
  tbb::parallel_for(size_t{0}, images.size(), [&](size_t i) {
    const dataset::View v = dataset::AtPyramidLevel(views[i], level);
    cv::Mat usable =
        v.mask.empty() ? cv::Mat(v.image.size(), CV_8UC1, cv::Scalar(255)) : (v.mask > 0);
    features[i] =
        patch::DetectFeatures(v.image, usable, options.feature_block, options.features_per_block);
  });
  if (progress) progress("features", images.size(), images.size());
  std::vector<camera::Camera> cameras;
  for (const auto& image : images) cameras.push_back(image.camera());
  Eigen::Vector3d scene_centre = NearestPointToAxes(cameras);
  if (!bounds.empty()) {
    scene_centre.setZero();
    for (const auto& c : bounds.occupied_centres) scene_centre += c.cast<double>();
    scene_centre /= static_cast<double>(bounds.occupied_centres.size());
  }
  NeighbourOptions neighbour_options;
  neighbour_options.max_neighbours = options.seed_neighbours;
  const auto neighbours = SelectNeighbours(cameras, scene_centre, neighbour_options);
  const auto fallback = FallbackDepths(images, scene_centre);

  // Seeds, one image at a time: its features in parallel against the grid as it stands, then
  // committed in feature order unless an earlier commit filled the cell.
  PatchSet set;
  CellGrids grids(images, options.cell_size);
  const patch::SeedFinder seeds(images, features, neighbours, fallback, options);
  for (uint32_t i = 0; i < images.size(); ++i) {
    const patch::PatchRefiner refiner(images, grids, lookup, options);
    std::vector<std::optional<Patch>> found(features[i].size());
    tbb::parallel_for(size_t{0}, features[i].size(), [&](size_t f) {
      int cx = 0, cy = 0;
      const Feature& feature = features[i][f];
      if (grids.CellOf(i, feature.u, feature.v, &cx, &cy) && !grids.Empty(i, cx, cy)) return;
      found[f] = seeds.FromFeature(i, feature, refiner);
    });
    for (auto& candidate : found) {
      if (!candidate) continue;
      int cx = 0, cy = 0;
      if (grids.CellOfPoint(i, images[i], candidate->centre, &cx, &cy) && !grids.Empty(i, cx, cy)) {
        continue;
      }
      const uint32_t id = set.Add(std::move(*candidate));
      grids.Add(id, set.patches[id], images);
    }
    if (progress) progress("seeds", i + 1, images.size());
  }

  for (int round = 0; round < options.rounds; ++round) {
    patch::Expand(set.AliveIds(), images, lookup, options, &set, &grids, progress);
    patch::FilterOutside(images, options, &set, &grids);
    patch::FilterExact(images, options, &set, &grids);
    patch::FilterRegularity(images, options, &set, &grids);
    patch::FilterSmallGroups(images, options, &set, &grids);
    if (progress) progress("rounds", round + 1, options.rounds);
  }
  return ToPoints(set, images);
}

}  // namespace avc::mvs
