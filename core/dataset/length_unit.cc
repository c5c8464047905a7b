#include "core/dataset/length_unit.h"

#include <fmt/format.h>

#include <stdexcept>
#include <utility>

#include "core/camera/axes_meeting_point.h"
#include "core/util/upper_median.h"

namespace avc::dataset {
namespace {

// Median distance from the camera centres to where their axes meet; with axes too close to
// parallel to meet (a single forward-looking sweep), the median distance to the centres' mean.
double MedianCameraDistance(const std::vector<camera::Camera>& cameras) {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  try {
    centre = camera::AxesMeetingPoint(cameras);
  } catch (const std::invalid_argument&) {
    for (const camera::Camera& camera : cameras) centre += camera.Centre();
    centre /= static_cast<double>(cameras.size());
  }
  std::vector<double> distances;
  for (const camera::Camera& camera : cameras) {
    distances.push_back((camera.Centre() - centre).norm());
  }
  return UpperMedian(std::move(distances));
}

bool Plausible(double distance, LengthUnit unit) {
  const double metres = distance * MetresPerUnit(unit);
  return metres >= kMinCameraDistanceM && metres <= kMaxCameraDistanceM;
}

}  // namespace

std::string LengthUnitName(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::kMetre:
      return "m";
    case LengthUnit::kMillimetre:
      return "mm";
    case LengthUnit::kAuto:
      break;
  }
  return "auto";
}

LengthUnit ParseLengthUnit(const std::string& text) {
  for (LengthUnit unit : {LengthUnit::kAuto, LengthUnit::kMetre, LengthUnit::kMillimetre}) {
    if (text == LengthUnitName(unit)) return unit;
  }
  throw std::invalid_argument(fmt::format("unknown length unit '{}' (choose m, mm or auto)", text));
}

double MetresPerUnit(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::kMetre:
      return 1.0;
    case LengthUnit::kMillimetre:
      return 1e-3;
    case LengthUnit::kAuto:
      break;
  }
  throw std::invalid_argument("MetresPerUnit: 'auto' is not a unit");
}

UnitDecision DecideLengthUnit(const std::vector<camera::Camera>& cameras, LengthUnit requested,
                              LengthUnit declared, const std::string& declared_by,
                              const std::string& dataset) {
  if (cameras.empty()) throw std::runtime_error(dataset + ": no cameras to take a unit from");
  UnitDecision decision;
  decision.camera_distance = MedianCameraDistance(cameras);
  const double d = decision.camera_distance;
  const std::string evidence =
      fmt::format("cameras a median {:.4g} units from the scene's centre", d);
  if (requested != LengthUnit::kAuto || declared != LengthUnit::kAuto) {
    decision.unit = requested != LengthUnit::kAuto ? requested : declared;
    const std::string source = requested != LengthUnit::kAuto ? "--units" : declared_by;
    if (!Plausible(d, decision.unit)) {
      throw std::runtime_error(fmt::format(
          "{}: {} says {}, but then the cameras are {:.4g} m from the scene ({}; a scanning "
          "set-up has {}-{} m); check the unit",
          dataset, source, LengthUnitName(decision.unit), d * MetresPerUnit(decision.unit),
          evidence, kMinCameraDistanceM, kMaxCameraDistanceM));
    }
    decision.how = fmt::format("{} (from {}; {})", LengthUnitName(decision.unit), source, evidence);
    return decision;
  }
  for (LengthUnit unit : {LengthUnit::kMetre, LengthUnit::kMillimetre}) {
    if (Plausible(d, unit)) {
      decision.unit = unit;
      decision.how = fmt::format("{} (automatic: {}, i.e. {:.3g} m)", LengthUnitName(unit),
                                 evidence, d * MetresPerUnit(unit));
      return decision;
    }
  }
  throw std::runtime_error(fmt::format(
      "{}: cannot tell the length unit: {}, which is neither {}-{} m nor {}-{} mm as a scanning "
      "set-up has; pass --units m or --units mm",
      dataset, evidence, kMinCameraDistanceM, kMaxCameraDistanceM, kMinCameraDistanceM * 1e3,
      kMaxCameraDistanceM * 1e3));
}

}  // namespace avc::dataset
