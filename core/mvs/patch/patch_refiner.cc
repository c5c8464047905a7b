#include "core/mvs/patch/patch_refiner.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/mvs/patch/nelder_mead.h"

namespace avc::mvs::patch {

struct PatchRefiner::Frame {
  Eigen::Vector3d centre;
  Eigen::Vector3d xaxis;  // one grid step, about one reference pixel
  Eigen::Vector3d yaxis;
};

namespace {

float Dot(const float* a, const float* b, int n) {
  float sum = 0;
  for (int i = 0; i < n; ++i) sum += a[i] * b[i];
  return sum;
}

// Pixels per metre along direction d at a point with homogeneous projection h.
double PixelRate(const PatchImage& image, const Eigen::Vector3d& h, const Eigen::Vector3d& d) {
  const Eigen::Vector3d dh = image.ProjectDirection(d);
  const double du = (dh.x() * h.z() - h.x() * dh.z()) / (h.z() * h.z());
  const double dv = (dh.y() * h.z() - h.y() * dh.z()) / (h.z() * h.z());
  return std::hypot(du, dv);
}

}  // namespace

PatchRefiner::PatchRefiner(const std::vector<PatchImage>& images, const CellGrids& grids,
                           const OccupancyLookup& lookup, const PatchMvsOptions& options)
    : images_(images),
      grids_(grids),
      lookup_(lookup),
      options_(options),
      cos_max_angle_(std::cos(options.max_view_angle)) {}

std::vector<uint32_t> PatchRefiner::VisibleImages(const Patch& patch) const {
  std::vector<uint32_t> visible;
  const double margin = options_.window / 2;
  for (uint32_t j = 0; j < images_.size(); ++j) {
    const PatchImage& image = images_[j];
    const Eigen::Vector3d h = image.ProjectH(patch.centre);
    if (h.z() <= 0) continue;
    const double u = h.x() / h.z(), v = h.y() / h.z();
    if (!image.Inside(u, v, margin) || !image.Usable(u, v)) continue;
    const Eigen::Vector3d to_camera = (image.centre() - patch.centre).normalized();
    if (to_camera.dot(patch.normal) < cos_max_angle_) continue;
    int cx = 0, cy = 0;
    if (grids_.CellOf(j, u, v, &cx, &cy)) {
      const double tolerance =
          grids_.OcclusionTolerance(options_.occlusion_cells, h.z(), image.fx());
      if (grids_.NearestDepth(j, cx, cy) < h.z() - tolerance) continue;
    }
    visible.push_back(j);
  }
  return visible;
}

bool PatchRefiner::MakeFrame(const Eigen::Vector3d& centre, const Eigen::Vector3d& normal,
                             uint32_t ref, Frame* frame) const {
  const PatchImage& image = images_[ref];
  const Eigen::Vector3d h = image.ProjectH(centre);
  if (h.z() <= 0) return false;
  const Eigen::Matrix3d rotation = image.camera().T_cam_world.linear();
  Eigen::Vector3d x = rotation.row(0).transpose();
  x -= normal * normal.dot(x);
  if (x.norm() < 1e-6) return false;
  x.normalize();
  const Eigen::Vector3d y = normal.cross(x);
  const double rate_x = PixelRate(image, h, x), rate_y = PixelRate(image, h, y);
  if (rate_x < 1e-9 || rate_y < 1e-9) return false;
  frame->centre = centre;
  frame->xaxis = x / rate_x;
  frame->yaxis = y / rate_y;
  return true;
}

bool PatchRefiner::SampleNormalised(const Frame& frame, uint32_t image_index, float* out,
                                    double min_deviation) const {
  const PatchImage& image = images_[image_index];
  const int half = options_.window / 2;
  // The grid maps to the image by a homography: step it in float homogeneous coordinates.
  const Eigen::Vector3f hc = image.ProjectH(frame.centre).cast<float>();
  const Eigen::Vector3f hx = image.ProjectDirection(frame.xaxis).cast<float>();
  const Eigen::Vector3f hy = image.ProjectDirection(frame.yaxis).cast<float>();
  const float max_u = static_cast<float>(image.width() - 1);
  const float max_v = static_cast<float>(image.height() - 1);
  float* o = out;
  float sum[3] = {0, 0, 0};
  for (int b = -half; b <= half; ++b) {
    const float rx = hc.x() + b * hy.x(), ry = hc.y() + b * hy.y(), rz = hc.z() + b * hy.z();
    for (int a = -half; a <= half; ++a) {
      const float z = rz + a * hx.z();
      if (z <= 0) return false;
      const float inverse = 1.0f / z;
      const float u = (rx + a * hx.x()) * inverse, v = (ry + a * hx.y()) * inverse;
      if (!(u >= 0 && v >= 0 && u <= max_u && v <= max_v)) return false;
      image.Sample(u, v, o);
      for (int c = 0; c < 3; ++c) sum[c] += o[c];
      o += 3;
    }
  }
  if (options_.whole_patch_in_mask > 0) {
    // The corners too: a patch straddling the silhouette matches its (view-dependent) edge.
    for (int b : {-half, half}) {
      for (int a : {-half, half}) {
        const Eigen::Vector3f h = hc + static_cast<float>(a) * hx + static_cast<float>(b) * hy;
        if (!image.Usable(h.x() / h.z(), h.y() / h.z())) return false;
      }
    }
  }
  // Each channel loses its own mean (as PMVS normalises): with one mean over R, G and B the
  // difference between the channels would count as texture, and a uniform green leaf would
  // correlate perfectly with any other piece of the same green at any depth.
  const int n = static_cast<int>(o - out);
  const float pixels = static_cast<float>(n / 3);
  const float mean[3] = {sum[0] / pixels, sum[1] / pixels, sum[2] / pixels};
  double squares = 0;
  for (int i = 0; i < n; i += 3) {
    for (int c = 0; c < 3; ++c) {
      out[i + c] -= mean[c];
      squares += static_cast<double>(out[i + c]) * out[i + c];
    }
  }
  if (squares <= 1e-12 || std::sqrt(squares / n) < min_deviation) return false;
  const float scale = static_cast<float>(1.0 / std::sqrt(squares));
  for (int i = 0; i < n; ++i) out[i] *= scale;
  return true;
}

bool PatchRefiner::Refine(Patch* patch) const {
  const uint32_t ref = patch->reference;
  const PatchImage& ref_image = images_[ref];
  const int n = 3 * options_.window * options_.window;
  std::vector<float> ref_samples(n), samples(n);

  std::vector<uint32_t> visible = VisibleImages(*patch);
  if (!std::binary_search(visible.begin(), visible.end(), ref)) return false;
  Frame frame;
  if (!MakeFrame(patch->centre, patch->normal, ref, &frame) ||
      !SampleNormalised(frame, ref, ref_samples.data(), options_.min_texture)) {
    return false;
  }
  std::vector<std::pair<float, uint32_t>> agreeing;
  for (uint32_t j : visible) {
    if (j == ref || !SampleNormalised(frame, j, samples.data(), 0)) continue;
    const float ncc = Dot(ref_samples.data(), samples.data(), n);
    if (ncc >= options_.ncc_threshold_before) agreeing.push_back({ncc, j});
  }
  if (static_cast<int>(agreeing.size()) + 1 < options_.min_images) return false;
  std::stable_sort(agreeing.begin(), agreeing.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  if (static_cast<int>(agreeing.size()) > options_.max_refine_images) {
    agreeing.resize(options_.max_refine_images);
  }

  // Depth along the reference ray in steps of two reference pixel footprints; the normal as
  // offsets in its tangent plane.
  const Eigen::Vector3d c0 = patch->centre, n0 = patch->normal;
  const Eigen::Vector3d ray = (c0 - ref_image.centre()).normalized();
  const double unit = 2.0 * ref_image.Depth(c0) / ref_image.fx();
  const Eigen::Vector3d t1 = n0.unitOrthogonal(), t2 = n0.cross(t1);
  auto geometry = [&](const NmPoint<3>& x, Eigen::Vector3d* c, Eigen::Vector3d* nrm) {
    *c = c0 + x[0] * unit * ray;
    *nrm = (n0 + x[1] * t1 + x[2] * t2).normalized();
  };
  auto cost = [&](const NmPoint<3>& x) {
    Eigen::Vector3d c, nrm;
    geometry(x, &c, &nrm);
    if ((ref_image.centre() - c).normalized().dot(nrm) < cos_max_angle_) return 2.0;
    Frame f;
    if (!MakeFrame(c, nrm, ref, &f) ||
        !SampleNormalised(f, ref, ref_samples.data(), options_.min_texture)) {
      return 2.0;
    }
    double sum = 0;
    for (const auto& [ncc0, j] : agreeing) {
      sum += SampleNormalised(f, j, samples.data(), 0)
                 ? 1.0 - Dot(ref_samples.data(), samples.data(), n)
                 : 2.0;
    }
    return sum / agreeing.size();
  };
  double best_cost = 0;
  const NmPoint<3> best =
      NelderMead<3>(cost, {0, 0, 0}, {1.0, 0.15, 0.15}, options_.max_iterations, 1e-3, &best_cost);
  if (best_cost >= 2.0) return false;
  geometry(best, &patch->centre, &patch->normal);
  if (!lookup_.Contains(patch->centre, options_.bounds_dilation)) return false;

  // The final V*: every visible image that agrees after refinement.
  visible = VisibleImages(*patch);
  if (!std::binary_search(visible.begin(), visible.end(), ref)) return false;
  if (!MakeFrame(patch->centre, patch->normal, ref, &frame) ||
      !SampleNormalised(frame, ref, ref_samples.data(), options_.min_texture)) {
    return false;
  }
  patch->visible.clear();
  double sum = 0;
  for (uint32_t j : visible) {
    if (j == ref) {
      patch->visible.push_back(j);
      continue;
    }
    if (!SampleNormalised(frame, j, samples.data(), 0)) continue;
    const float ncc = Dot(ref_samples.data(), samples.data(), n);
    if (ncc < options_.ncc_threshold) continue;
    patch->visible.push_back(j);
    sum += ncc;
  }
  if (static_cast<int>(patch->visible.size()) < options_.min_images) return false;
  patch->score = static_cast<float>(sum / (patch->visible.size() - 1));
  return true;
}

}  // namespace avc::mvs::patch
