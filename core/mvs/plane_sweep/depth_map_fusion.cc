#include "core/mvs/plane_sweep/depth_map_fusion.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include "core/mvs/occupancy_lookup.h"

namespace avc::mvs {
namespace {

struct Candidate {
  Eigen::Vector3f position;
  Eigen::Vector3f normal;
  Eigen::Matrix<uint8_t, 3, 1> rgb;
  float confidence = 0;
  std::vector<uint32_t> views;
};

Eigen::Vector3d BackProject(const camera::Camera& camera, double x, double y, double depth) {
  const camera::Intrinsics& k = camera.intrinsics;
  const Eigen::Vector3d p_cam(depth * (x - k.cx) / k.fx, depth * (y - k.cy) / k.fy, depth);
  return camera.T_cam_world.inverse() * p_cam;
}

bool Usable(const SweepDepthMap& map, int x, int y, float min_score) {
  return map.depth.at<float>(y, x) > 0 && map.score.at<float>(y, x) >= min_score;
}

// Normal of the depth map at (x, y) from back-projected points `step` pixels apart (central
// differences, one-sided where a side has no depth), facing the camera; the direction to the
// camera where neither works.
Eigen::Vector3d DepthMapNormal(const SweepView& view, const SweepDepthMap& map, int x, int y,
                               int step, float min_score, const Eigen::Vector3d& point) {
  const int width = map.depth.cols;
  const int height = map.depth.rows;
  auto point_at = [&](int px, int py, Eigen::Vector3d& out) {
    if (px < 0 || py < 0 || px >= width || py >= height || !Usable(map, px, py, min_score)) {
      return false;
    }
    out = BackProject(view.camera, px, py, map.depth.at<float>(py, px));
    return true;
  };
  auto difference = [&](int dx, int dy, Eigen::Vector3d& out) {
    Eigen::Vector3d plus, minus;
    const bool has_plus = point_at(x + dx, y + dy, plus);
    const bool has_minus = point_at(x - dx, y - dy, minus);
    if (has_plus && has_minus)
      out = plus - minus;
    else if (has_plus)
      out = plus - point;
    else if (has_minus)
      out = point - minus;
    else
      return false;
    return true;
  };
  const Eigen::Vector3d to_camera = (view.camera.Centre() - point).normalized();
  Eigen::Vector3d along_x, along_y;
  if (!difference(step, 0, along_x) || !difference(0, step, along_y)) return to_camera;
  Eigen::Vector3d normal = along_x.cross(along_y);
  if (!(normal.norm() > 0)) return to_camera;
  normal.normalize();
  return normal.dot(to_camera) < 0 ? Eigen::Vector3d(-normal) : normal;
}

Eigen::Vector3d ColourAt(const SweepView& view, const Eigen::Vector2d& pixel) {
  const int x = std::clamp(static_cast<int>(std::lround(pixel.x())), 0, view.colour.cols - 1);
  const int y = std::clamp(static_cast<int>(std::lround(pixel.y())), 0, view.colour.rows - 1);
  const cv::Vec3b bgr = view.colour.at<cv::Vec3b>(y, x);
  return Eigen::Vector3d(bgr[2], bgr[1], bgr[0]);
}

// One reference view's fused points, in pixel order.
std::vector<Candidate> FuseReference(size_t r, const std::vector<SweepView>& views,
                                     const std::vector<SweepDepthMap>& maps,
                                     const OccupancyLookup& inside,
                                     const PlaneSweepOptions& options) {
  std::vector<Candidate> out;
  const SweepView& ref = views[r];
  const SweepDepthMap& map = maps[r];
  const float min_score = static_cast<float>(options.min_score);
  for (int y = 0; y < map.depth.rows; ++y) {
    for (int x = 0; x < map.depth.cols; ++x) {
      if (!Usable(map, x, y, min_score)) continue;
      const Eigen::Vector3d point = BackProject(ref.camera, x, y, map.depth.at<float>(y, x));
      if (!inside.Contains(point, 1)) continue;
      Eigen::Vector3d position_sum = point;
      Eigen::Vector3d colour_sum = ColourAt(ref, Eigen::Vector2d(x, y));
      double score_sum = map.score.at<float>(y, x);
      std::vector<uint32_t> seen_by = {static_cast<uint32_t>(r)};
      for (size_t v = 0; v < views.size(); ++v) {
        if (v == r) continue;
        const std::optional<Eigen::Vector2d> pixel = views[v].camera.Project(point);
        if (!pixel) continue;
        const int qx = static_cast<int>(std::lround(pixel->x()));
        const int qy = static_cast<int>(std::lround(pixel->y()));
        if (qx < 0 || qy < 0 || qx >= maps[v].depth.cols || qy >= maps[v].depth.rows) continue;
        if (!Usable(maps[v], qx, qy, min_score)) continue;
        const double expected = (views[v].camera.T_cam_world * point).z();
        const double found = maps[v].depth.at<float>(qy, qx);
        if (std::abs(found - expected) > options.consistency_tolerance * expected) continue;
        // The other view's estimate along its own ray through the point.
        position_sum += BackProject(views[v].camera, pixel->x(), pixel->y(), found);
        colour_sum += ColourAt(views[v], *pixel);
        score_sum += maps[v].score.at<float>(qy, qx);
        seen_by.push_back(static_cast<uint32_t>(v));
      }
      if (static_cast<int>(seen_by.size()) - 1 < options.min_consistent_views) continue;
      const double count = static_cast<double>(seen_by.size());
      Candidate candidate;
      candidate.position = (position_sum / count).cast<float>();
      // Face the seeing cameras on average (a normal nearly along the surface could otherwise
      // face the reference camera but point away from the others).
      Eigen::Vector3d normal =
          DepthMapNormal(ref, map, x, y, options.normal_step_px, min_score, point);
      Eigen::Vector3d towards_cameras = Eigen::Vector3d::Zero();
      for (uint32_t v : seen_by) towards_cameras += (views[v].camera.Centre() - point).normalized();
      if (normal.dot(towards_cameras) < 0) normal = -normal;
      candidate.normal = normal.cast<float>();
      const Eigen::Vector3d colour = (colour_sum / count).array().round();
      candidate.rgb = colour.cast<uint8_t>();
      candidate.confidence = static_cast<float>(std::clamp(score_sum / count, 0.0, 1.0));
      std::sort(seen_by.begin(), seen_by.end());
      candidate.views = std::move(seen_by);
      out.push_back(std::move(candidate));
    }
  }
  return out;
}

// The size of one pixel on the surface: median over views of median depth / focal length.
double PixelFootprint(const std::vector<SweepView>& views, const std::vector<SweepDepthMap>& maps,
                      float min_score) {
  std::vector<double> footprints;
  for (size_t v = 0; v < views.size(); ++v) {
    std::vector<float> depths;
    for (int y = 0; y < maps[v].depth.rows; ++y) {
      for (int x = 0; x < maps[v].depth.cols; ++x) {
        if (Usable(maps[v], x, y, min_score)) depths.push_back(maps[v].depth.at<float>(y, x));
      }
    }
    if (depths.empty()) continue;
    std::nth_element(depths.begin(), depths.begin() + depths.size() / 2, depths.end());
    footprints.push_back(depths[depths.size() / 2] / views[v].camera.intrinsics.fx);
  }
  if (footprints.empty()) return 0;
  std::nth_element(footprints.begin(), footprints.begin() + footprints.size() / 2,
                   footprints.end());
  return footprints[footprints.size() / 2];
}

}  // namespace

MvsPoints FuseDepthMaps(const std::vector<SweepView>& views,
                        const std::vector<SweepDepthMap>& depth_maps, const MvsBounds& bounds,
                        const PlaneSweepOptions& options) {
  const OccupancyLookup inside(bounds);
  std::vector<std::vector<Candidate>> per_view(views.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, views.size(), 1),
                    [&](const tbb::blocked_range<size_t>& range) {
                      for (size_t r = range.begin(); r != range.end(); ++r) {
                        per_view[r] = FuseReference(r, views, depth_maps, inside, options);
                      }
                    });
  std::vector<Candidate> candidates;
  for (std::vector<Candidate>& list : per_view) {
    for (Candidate& c : list) candidates.push_back(std::move(c));
  }

  // Deduplicate: the most confident point per cell (ties by reference view and pixel order).
  const double cell =
      options.cell_px * PixelFootprint(views, depth_maps, static_cast<float>(options.min_score));
  std::vector<std::array<int64_t, 3>> keys(candidates.size());
  for (size_t i = 0; i < candidates.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      keys[i][static_cast<size_t>(a)] =
          cell > 0 ? static_cast<int64_t>(std::floor(candidates[i].position[a] / cell))
                   : static_cast<int64_t>(i);
    }
  }
  std::vector<size_t> order(candidates.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    if (keys[a] != keys[b]) return keys[a] < keys[b];
    if (candidates[a].confidence != candidates[b].confidence) {
      return candidates[a].confidence > candidates[b].confidence;
    }
    return a < b;
  });
  std::vector<size_t> kept;
  for (size_t i = 0; i < order.size(); ++i) {
    if (i == 0 || keys[order[i]] != keys[order[i - 1]]) kept.push_back(order[i]);
  }
  std::sort(kept.begin(), kept.end());  // back to reference-view and pixel order

  MvsPoints points;
  for (size_t i : kept) {
    Candidate& c = candidates[i];
    points.cloud.positions.push_back(c.position);
    points.cloud.normals.push_back(c.normal);
    points.cloud.colors.push_back(c.rgb);
    points.confidence.push_back(c.confidence);
    points.views.push_back(std::move(c.views));
  }
  return points;
}

}  // namespace avc::mvs
