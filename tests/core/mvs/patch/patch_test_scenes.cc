#include "tests/core/mvs/patch/patch_test_scenes.h"

#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <random>
#include <stdexcept>

#include "core/dataset/dataset_reader.h"
#include "core/dataset/view_transforms.h"
#include "core/eval/silhouette_agreement.h"
#include "core/geometry/mesh_io.h"
#include "core/segmentation/threshold_silhouette.h"
#include "sim/dataset/render_dataset.h"

namespace avc::mvs::testing {

cv::Mat DinoSilhouette(const cv::Mat& bgr) {
  return segmentation::ThresholdSilhouette(bgr, 0.19, 10, 7);
}

MvsBounds VisualHull(const std::vector<dataset::View>& views, const Eigen::Vector3d& lo,
                     const Eigen::Vector3d& hi, double voxel, int misses) {
  MvsBounds bounds;
  bounds.voxel_size = voxel;
  const Eigen::Vector3i n = ((hi - lo) / voxel).array().ceil().cast<int>();
  for (int z = 0; z < n.z(); ++z) {
    for (int y = 0; y < n.y(); ++y) {
      for (int x = 0; x < n.x(); ++x) {
        const Eigen::Vector3d c = lo + voxel * (Eigen::Vector3d(x, y, z).array() + 0.5).matrix();
        int outside = 0;
        for (const auto& v : views) {
          const auto pixel = v.camera.Project(c);
          if (!pixel) continue;
          const int u = static_cast<int>(std::lround(pixel->x()));
          const int w = static_cast<int>(std::lround(pixel->y()));
          if (u < 0 || w < 0 || u >= v.mask.cols || w >= v.mask.rows) continue;
          if (v.mask.at<uint8_t>(w, u) == 0) ++outside;
        }
        if (outside <= misses) bounds.occupied_centres.push_back(c.cast<float>());
      }
    }
  }
  return bounds;
}

double InsideFraction(const MvsPoints& points, const std::vector<dataset::View>& views,
                      const std::vector<cv::Mat>& silhouettes) {
  return eval::InsideAllSilhouettesFraction(points, views, silhouettes);
}

std::vector<dataset::View> TexturedPlaneViews(int count, int width, int height, double distance,
                                              double side, uint32_t seed) {
  // Texture: seeded noise (own mapping from rng bits), blurred so it is band-limited.
  constexpr int kTexture = 512;
  std::mt19937 rng(seed);
  cv::Mat texture(kTexture, kTexture, CV_32FC3);
  for (int y = 0; y < kTexture; ++y) {
    for (int x = 0; x < kTexture; ++x) {
      for (int c = 0; c < 3; ++c) texture.at<cv::Vec3f>(y, x)[c] = static_cast<float>(rng() >> 24);
    }
  }
  cv::GaussianBlur(texture, texture, cv::Size(), 1.5);
  cv::normalize(texture, texture, 20, 235, cv::NORM_MINMAX);

  std::vector<dataset::View> views;
  const double f = 0.9 * width;
  for (int i = 0; i < count; ++i) {
    const double azimuth = 2 * M_PI * i / count;
    const double elevation = 1.1;  // radians above the plane
    const Eigen::Vector3d centre =
        distance * Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth),
                                   std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
    const Eigen::Vector3d z = -centre.normalized();
    const Eigen::Vector3d x = z.cross(Eigen::Vector3d::UnitZ()).normalized();
    const Eigen::Vector3d y = z.cross(x);
    Eigen::Matrix3d r;
    r.row(0) = x.transpose();
    r.row(1) = y.transpose();
    r.row(2) = z.transpose();
    dataset::View view;
    view.name = "plane_" + std::to_string(i);
    auto& k = view.camera.intrinsics;
    k.width = width, k.height = height, k.fx = f, k.fy = f, k.cx = (width - 1) / 2.0,
    k.cy = (height - 1) / 2.0;
    view.camera.T_cam_world.linear() = r;
    view.camera.T_cam_world.translation() = -r * centre;
    // Each pixel's ray meets z = 0 at a texture coordinate: sample it (bilinear) by remap.
    cv::Mat map_x(height, width, CV_32F), map_y(height, width, CV_32F);
    view.mask = cv::Mat(height, width, CV_8UC1, cv::Scalar(0));
    for (int v = 0; v < height; ++v) {
      for (int u = 0; u < width; ++u) {
        const Eigen::Vector3d ray = r.transpose() * k.Ray({double(u), double(v)});
        const double t = -centre.z() / ray.z();
        const Eigen::Vector3d p = centre + t * ray;
        map_x.at<float>(v, u) = static_cast<float>((p.x() / side + 0.5) * kTexture - 0.5);
        map_y.at<float>(v, u) = static_cast<float>((p.y() / side + 0.5) * kTexture - 0.5);
        if (std::abs(p.x()) < 0.45 * side && std::abs(p.y()) < 0.45 * side) {
          view.mask.at<uint8_t>(v, u) = 255;
        }
      }
    }
    cv::Mat image;
    cv::remap(texture, image, map_x, map_y, cv::INTER_LINEAR, cv::BORDER_CONSTANT);
    image.convertTo(view.image, CV_8UC3);
    views.push_back(std::move(view));
  }
  return views;
}

SimScan RenderScan(const std::filesystem::path& dir, int preset, int views, int width, int height) {
  sim::RenderDatasetOptions options;
  options.preset = sim::AllPresets().at(preset);
  options.views = views;
  options.width = width;
  options.height = height;
  options.output = dir;
  sim::RenderDataset(options);
  SimScan scan;
  dataset::ViewSet set = dataset::ReadDataset(dir);
  for (auto& view : set.views) {
    const std::filesystem::path stem = std::filesystem::path(view.name).stem();
    const cv::Mat labels =
        cv::imread((dir / "labels" / (stem.string() + ".png")).string(), cv::IMREAD_UNCHANGED);
    if (labels.empty()) throw std::runtime_error("no label image for " + view.name);
    view.mask = labels > 0;
    scan.raw_distortion.push_back(view.camera.intrinsics.distortion);
    dataset::Undistort(view);  // the simulated camera has lens distortion; MVS wants none
  }
  scan.views = std::move(set.views);
  scan.ground_truth = geometry::ReadMesh(dir / "gt_mesh.ply");
  Eigen::Vector3f lo, hi;
  geometry::Bounds(scan.ground_truth, &lo, &hi);
  scan.lo = lo.cast<double>() - Eigen::Vector3d::Constant(0.01);
  scan.hi = hi.cast<double>() + Eigen::Vector3d::Constant(0.01);
  return scan;
}

}  // namespace avc::mvs::testing
