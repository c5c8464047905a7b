#include "core/eval/coverage.h"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>

#include "core/eval/triangle_tree.h"
#include "core/util/validation.h"

namespace avc::eval {
namespace {

// With lens distortion a point far outside the field of view can map back into the image (the
// distortion polynomial folds over); a real view ray through its pixel points elsewhere.
bool ProjectsFaithfully(const camera::Intrinsics& intrinsics, const Eigen::Vector3d& p_cam,
                        const Eigen::Vector2d& pixel) {
  if (!intrinsics.HasDistortion()) return true;
  return (intrinsics.Ray(pixel) - p_cam.normalized()).norm() < 1e-4;
}

bool InsideImage(const camera::Intrinsics& intrinsics, const Eigen::Vector2d& pixel) {
  // Pixel centres are at integers, so the image spans [-0.5, size - 0.5).
  return pixel.x() >= -0.5 && pixel.x() < intrinsics.width - 0.5 && pixel.y() >= -0.5 &&
         pixel.y() < intrinsics.height - 0.5;
}

}  // namespace

std::string CoverageOptions::Validate() const {
  if (min_views < 1) {
    return fmt::format("coverage: min_views {} must be at least 1", min_views);
  }
  if (!(max_grazing_deg > 0 && max_grazing_deg <= 90)) {
    return fmt::format("coverage: max grazing angle {} deg must be in (0, 90]", max_grazing_deg);
  }
  if (!(occlusion_epsilon >= 0) || !std::isfinite(occlusion_epsilon)) {
    return fmt::format("coverage: occlusion epsilon {} must be non-negative and finite",
                       occlusion_epsilon);
  }
  return {};
}

void ValidateCamera(const camera::Camera& camera, const std::string& what) {
  if (const std::string problem = camera.intrinsics.Validate(); !problem.empty()) {
    throw std::invalid_argument(fmt::format("{}: {}", what, problem));
  }
  if (!camera.T_cam_world.matrix().allFinite()) {
    throw std::invalid_argument(fmt::format("{}: T_cam_world is not finite", what));
  }
  const Eigen::Matrix3d rotation = camera.T_cam_world.linear();
  if (!(rotation.transpose() * rotation).isIdentity(1e-6) || !(rotation.determinant() > 0)) {
    throw std::invalid_argument(fmt::format("{}: T_cam_world's rotation is not orthonormal", what));
  }
}

CoverageModel::CoverageModel(const geometry::Mesh& ground_truth, double samples_per_m2,
                             uint64_t seed, const CoverageOptions& options, size_t max_samples)
    : CoverageModel(ground_truth, SampleSurface(ground_truth, samples_per_m2, seed, max_samples),
                    options) {}

CoverageModel::CoverageModel(const geometry::Mesh& ground_truth, SurfaceSamples samples,
                             const CoverageOptions& options)
    : face_labels_(ground_truth.face_labels), samples_(std::move(samples)), options_(options) {
  RequireValid(options_);
  tree_ = std::make_unique<TriangleTree>(ground_truth, "ground truth mesh");
  if (samples_.normals.size() != samples_.size() || samples_.faces.size() != samples_.size()) {
    throw std::invalid_argument(fmt::format(
        "coverage: {} samples with {} normals and {} faces; expected one of each per sample",
        samples_.size(), samples_.normals.size(), samples_.faces.size()));
  }
  for (int32_t face : samples_.faces) {
    if (face < 0 || static_cast<size_t>(face) >= ground_truth.num_faces()) {
      throw std::invalid_argument(
          fmt::format("coverage: a sample refers to face {} of a ground truth with {} faces", face,
                      ground_truth.num_faces()));
    }
  }
  if (samples_.size() == 0) {
    throw std::invalid_argument("coverage: the ground truth gave no surface samples");
  }
}

CoverageModel::~CoverageModel() = default;

std::vector<uint8_t> CoverageModel::SeenBy(const camera::Camera& camera) const {
  ValidateCamera(camera, "camera");
  const Eigen::Vector3d centre = camera.Centre();
  const double min_cosine = std::cos(options_.max_grazing_deg * std::numbers::pi / 180);
  std::vector<uint8_t> seen(samples_.size(), 0);
  auto sees = [&](size_t i) {
    const Eigen::Vector3d& p = samples_.points[i];
    const Eigen::Vector3d p_cam = camera.T_cam_world * p;
    const std::optional<Eigen::Vector2d> pixel = camera.intrinsics.Project(p_cam);
    if (!pixel || !InsideImage(camera.intrinsics, *pixel) ||
        !ProjectsFaithfully(camera.intrinsics, p_cam, *pixel)) {
      return false;
    }
    const Eigen::Vector3d to_camera = centre - p;
    const double length = to_camera.norm();
    if (!(length > options_.occlusion_epsilon)) return false;
    const Eigen::Vector3d direction = to_camera / length;
    if (std::abs(direction.dot(samples_.normals[i].cast<double>())) < min_cosine) return false;
    return !tree_->SegmentHits(centre, p + options_.occlusion_epsilon * direction);
  };
  tbb::parallel_for(tbb::blocked_range<size_t>(0, samples_.size(), 256),
                    [&](const tbb::blocked_range<size_t>& r) {
                      for (size_t i = r.begin(); i != r.end(); ++i) seen[i] = sees(i) ? 1 : 0;
                    });
  return seen;
}

std::vector<int> CoverageModel::ViewCounts(const std::vector<camera::Camera>& cameras) const {
  for (size_t c = 0; c < cameras.size(); ++c) {
    ValidateCamera(cameras[c], fmt::format("camera {}", c));
  }
  std::vector<int> counts(samples_.size(), 0);
  for (const camera::Camera& camera : cameras) {
    const std::vector<uint8_t> seen = SeenBy(camera);
    for (size_t i = 0; i < counts.size(); ++i) counts[i] += seen[i];
  }
  return counts;
}

CoverageResult CoverageModel::Evaluate(const std::vector<camera::Camera>& cameras) const {
  CoverageResult result;
  result.options = options_;
  result.cameras = cameras.size();
  result.samples = samples_.size();
  result.view_counts = ViewCounts(cameras);
  result.view_count_histogram.assign(static_cast<size_t>(options_.min_views) + 1, 0);
  std::map<int32_t, OrganCoverage> organs;
  for (size_t i = 0; i < result.view_counts.size(); ++i) {
    const int count = result.view_counts[i];
    const bool covered = count >= options_.min_views;
    result.covered += covered;
    ++result.view_count_histogram[static_cast<size_t>(std::min(count, options_.min_views))];
    if (!face_labels_.empty()) {
      OrganCoverage& organ = organs[face_labels_[static_cast<size_t>(samples_.faces[i])]];
      ++organ.samples;
      organ.covered += covered;
    }
  }
  result.fraction = static_cast<double>(result.covered) / static_cast<double>(result.samples);
  for (auto& [label, organ] : organs) {
    organ.label = label;
    organ.name = geometry::labels::Name(label);
    organ.fraction = static_cast<double>(organ.covered) / static_cast<double>(organ.samples);
    result.organs.push_back(organ);
  }
  return result;
}

}  // namespace avc::eval
