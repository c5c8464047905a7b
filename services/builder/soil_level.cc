#include "services/builder/soil_level.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "core/util/file_io.h"
#include "core/util/upper_median.h"
#include "core/util/validation.h"

namespace avc::builder {
namespace {

// Voxels within this height of the lowest one are the stem's base.
constexpr double kStemBaseBand = 0.01;
// Blur before sampling (pixels): grey levels then change smoothly with sub-pixel registration
// errors of the cameras.
constexpr double kBlurSigma = 1.0;
constexpr int kPatch = 5;  // samples across a patch
constexpr int kSamples = kPatch * kPatch;
constexpr double kPatchPitch = 0.0006;  // m between samples: a 2.4 mm patch
constexpr double kMinTexture = 2.0;     // grey levels (standard deviation over a patch)
constexpr double kNotSeen = -1.0;       // agreement of a patch too few views see

struct Stem {
  Eigen::Vector2d axis;
  double base_z = 0;
};

std::optional<Stem> StemBase(const mvs::MvsBounds& proxy) {
  const std::optional<float> lowest = proxy.LowestCentreZ();
  if (!lowest) return std::nullopt;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  int count = 0;
  for (const Eigen::Vector3f& c : proxy.occupied_centres) {
    if (c.z() > *lowest + kStemBaseBand) continue;
    sum += c.head<2>().cast<double>();
    ++count;
  }
  return Stem{sum / count, *proxy.BottomZ()};
}

std::vector<Eigen::Vector2d> Annulus(const Eigen::Vector2d& centre, const SoilLevelOptions& o) {
  std::vector<Eigen::Vector2d> points;
  for (double r = o.inner_radius; r <= o.outer_radius; r += o.sample_spacing) {
    const int around = std::max(8, static_cast<int>(2.0 * std::numbers::pi * r / o.sample_spacing));
    for (int k = 0; k < around; ++k) {
      const double angle = 2.0 * std::numbers::pi * k / around;
      points.push_back(centre + r * Eigen::Vector2d(std::cos(angle), std::sin(angle)));
    }
  }
  return points;
}

struct GreyView {
  const dataset::View* view;
  Eigen::Vector3d eye;  // the camera's centre, world
  cv::Mat grey;         // CV_32FC1, blurred
};

std::vector<GreyView> PrepareViews(const std::vector<dataset::View>& views) {
  std::vector<GreyView> prepared;
  for (const dataset::View& view : views) {
    if (view.mask.empty() || view.image.empty()) continue;
    GreyView grey{&view, view.camera.T_cam_world.inverse().translation(), {}};
    cv::Mat bytes;
    cv::cvtColor(view.image, bytes, cv::COLOR_BGR2GRAY);
    bytes.convertTo(grey.grey, CV_32FC1);
    cv::GaussianBlur(grey.grey, grey.grey, cv::Size(0, 0), kBlurSigma);
    prepared.push_back(std::move(grey));
  }
  return prepared;
}

// Bilinear grey level at a pixel (centres at integers); false outside the image or next to plant.
bool SampleBackground(const GreyView& view, const Eigen::Vector2d& pixel, double* grey) {
  const double u = pixel.x();
  const double v = pixel.y();
  // Compared before the conversion to int, which a far-off projection would overflow.
  if (!(u >= 0.0 && v >= 0.0 && u < view.grey.cols - 1 && v < view.grey.rows - 1)) return false;
  const int u0 = static_cast<int>(u);
  const int v0 = static_cast<int>(v);
  const cv::Mat& mask = view.view->mask;
  if (mask.at<uint8_t>(v0, u0) || mask.at<uint8_t>(v0, u0 + 1) || mask.at<uint8_t>(v0 + 1, u0) ||
      mask.at<uint8_t>(v0 + 1, u0 + 1)) {
    return false;
  }
  const double fu = u - u0;
  const double fv = v - v0;
  const auto at = [&](int row, int col) { return double{view.grey.at<float>(row, col)}; };
  *grey = (1 - fv) * ((1 - fu) * at(v0, u0) + fu * at(v0, u0 + 1)) +
          fv * ((1 - fu) * at(v0 + 1, u0) + fu * at(v0 + 1, u0 + 1));
  return true;
}

using Patch = std::array<double, kSamples>;

// The patch centred on `centre` in one view, zero-mean and unit-norm; false when part of it is
// not background in that view or it has no texture.
bool ViewPatch(const GreyView& view, const Eigen::Vector3d& centre, Patch* patch) {
  double mean = 0;
  for (int k = 0; k < kSamples; ++k) {
    const Eigen::Vector3d offset(k % kPatch - kPatch / 2, k / kPatch - kPatch / 2, 0);
    const std::optional<Eigen::Vector2d> pixel =
        view.view->camera.Project(centre + kPatchPitch * offset);
    if (!pixel || !SampleBackground(view, *pixel, &(*patch)[k])) return false;
    mean += (*patch)[k] / kSamples;
  }
  double norm = 0;
  for (double& g : *patch) {
    g -= mean;
    norm += g * g;
  }
  if (std::sqrt(norm / kSamples) < kMinTexture) return false;
  for (double& g : *patch) g /= std::sqrt(norm);
  return true;
}

// Mean correlation of the views' patches with their mean; kNotSeen when fewer than min_views
// views steep enough see the whole patch as textured background.
double PatchAgreement(const std::vector<GreyView>& views, const Eigen::Vector3d& centre,
                      const SoilLevelOptions& options) {
  const double min_sine = std::sin(options.min_elevation_deg * std::numbers::pi / 180.0);
  std::vector<Patch> patches;
  Patch patch;
  for (const GreyView& view : views) {
    const Eigen::Vector3d to_camera = view.eye - centre;
    if (to_camera.z() < min_sine * to_camera.norm()) continue;
    if (ViewPatch(view, centre, &patch)) patches.push_back(patch);
  }
  if (static_cast<int>(patches.size()) < options.min_views) return kNotSeen;
  Patch mean{};
  for (const Patch& p : patches)
    for (int k = 0; k < kSamples; ++k) mean[k] += p[k];
  double mean_norm = 0;
  for (double m : mean) mean_norm += m * m;
  mean_norm = std::sqrt(mean_norm);
  double agreement = 0;
  for (const Patch& p : patches) {
    double dot = 0;
    for (int k = 0; k < kSamples; ++k) dot += p[k] * mean[k];
    agreement += dot / mean_norm;
  }
  return agreement / static_cast<double>(patches.size());
}

struct Plane {
  double z = 0;
  double disagreement = 0;  // median over the seen patches of 1 - agreement
  size_t patches = 0;
};

// Planes with enough seen patches; each patch is scored in parallel into its own slot, so the
// result does not depend on the scheduling.
std::vector<Plane> Sweep(const std::vector<GreyView>& views,
                         const std::vector<Eigen::Vector2d>& annulus, double z_from, double z_to,
                         double step, const SoilLevelOptions& options) {
  std::vector<Plane> planes;
  const int count = static_cast<int>(std::floor((z_to - z_from) / step + 1e-9)) + 1;
  std::vector<double> agreement(annulus.size());
  for (int i = 0; i < count; ++i) {
    const double z = z_from + i * step;
    tbb::parallel_for(size_t{0}, annulus.size(), [&](size_t k) {
      agreement[k] = PatchAgreement(views, {annulus[k].x(), annulus[k].y(), z}, options);
    });
    std::vector<double> disagreement;
    for (double a : agreement) {
      if (a != kNotSeen) disagreement.push_back(1.0 - a);
    }
    if (static_cast<int>(disagreement.size()) < options.min_patches) continue;
    planes.push_back({z, UpperMedian(disagreement), disagreement.size()});
  }
  return planes;
}

const Plane& Best(const std::vector<Plane>& planes) {
  return *std::min_element(planes.begin(), planes.end(), [](const Plane& a, const Plane& b) {
    return a.disagreement < b.disagreement;
  });
}

}  // namespace

std::string SoilLevelOptions::Validate() const {
  FirstProblem problem;
  const auto require = [&problem](bool ok, const char* field, double value) {
    { problem.Require(ok, fmt::format("SoilLevelOptions.{} = {} is out of range", field, value)); }
  };
  require(inner_radius >= 0.0, "inner_radius", inner_radius);
  require(outer_radius > inner_radius, "outer_radius", outer_radius);
  require(sample_spacing > 0.0, "sample_spacing", sample_spacing);
  require(search_below >= 0.0, "search_below", search_below);
  require(search_above >= 0.0, "search_above", search_above);
  require(coarse_step > 0.0, "coarse_step", coarse_step);
  require(fine_step > 0.0 && fine_step <= coarse_step, "fine_step", fine_step);
  require(min_views >= 2, "min_views", min_views);
  require(min_patches >= 1, "min_patches", min_patches);
  require(min_elevation_deg >= 0.0 && min_elevation_deg < 90.0, "min_elevation_deg",
          min_elevation_deg);
  require(max_contrast >= 0.0, "max_contrast", max_contrast);
  return problem.text();
}

std::optional<SoilLevel> FindSoilLevel(const std::vector<dataset::View>& views,
                                       const mvs::MvsBounds& proxy, const SoilLevelOptions& options,
                                       std::string* why_not) {
  RequireValid(options);
  const auto none = [&](const std::string& reason) -> std::optional<SoilLevel> {
    if (why_not != nullptr) *why_not = reason;
    return std::nullopt;
  };
  if (!options.enabled) return none("the search is off (soil.enabled)");
  const std::optional<Stem> stem = StemBase(proxy);
  if (!stem) return none("the proxy is empty");
  const std::vector<GreyView> prepared = PrepareViews(views);
  if (static_cast<int>(prepared.size()) < options.min_views) {
    return none(fmt::format("{} views have a mask and an image; {} needed", prepared.size(),
                            options.min_views));
  }
  const std::vector<Eigen::Vector2d> annulus = Annulus(stem->axis, options);

  const std::vector<Plane> coarse =
      Sweep(prepared, annulus, stem->base_z - options.search_below,
            stem->base_z + options.search_above, options.coarse_step, options);
  if (coarse.size() < 3) {
    return none(fmt::format(
        "{} planes round the proxy's base had {} textured patches, each seen by {} views at "
        "least {} deg above it (3 such planes needed)",
        coarse.size(), options.min_patches, options.min_views, options.min_elevation_deg));
  }
  std::vector<double> disagreements;
  for (const Plane& plane : coarse) disagreements.push_back(plane.disagreement);
  const double typical = UpperMedian(disagreements);
  const double around = Best(coarse).z;
  const std::vector<Plane> fine = Sweep(prepared, annulus, around - options.coarse_step,
                                        around + options.coarse_step, options.fine_step, options);
  const Plane& best = fine.empty() ? Best(coarse) : Best(fine);
  const double contrast = typical > 0.0 ? best.disagreement / typical : 1.0;
  if (contrast > options.max_contrast) {
    return none(fmt::format(
        "no plane stands out: the best disagrees {:.2f} of the median plane, {:.2f} at most "
        "(plain or hidden soil)",
        contrast, options.max_contrast));
  }
  return SoilLevel{best.z, contrast, best.patches};
}

nlohmann::ordered_json SoilLevelToJson(const SoilLevel& soil) {
  return {{"z_m", soil.z}, {"contrast", soil.contrast}, {"patches", soil.patches}};
}

std::optional<SoilLevel> ReadSoilLevel(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file)) return std::nullopt;
  try {
    const nlohmann::json json = nlohmann::json::parse(ReadFile(file));
    return SoilLevel{json.at("z_m").get<double>(), json.at("contrast").get<double>(),
                     json.at("patches").get<size_t>()};
  } catch (const std::exception& error) {
    throw std::runtime_error(fmt::format("{}: not a soil level ({})", file.string(), error.what()));
  }
}

}  // namespace avc::builder
