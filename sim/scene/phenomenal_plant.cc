#include "sim/scene/phenomenal_plant.h"

#include <fmt/format.h>

#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

#include "core/geometry/mesh_io.h"

namespace avc::sim {
namespace {

struct SkeletonPoint {
  Eigen::Vector3f position;
  float width;
};

using Polyline = std::vector<SkeletonPoint>;

Polyline ParsePolyline(const nlohmann::json& points, const std::string& where) {
  if (!points.is_array() || points.size() < 2) {
    throw std::runtime_error(fmt::format("{}: expected a list of at least 2 points", where));
  }
  Polyline polyline;
  for (size_t k = 0; k < points.size(); ++k) {
    const nlohmann::json& p = points[k];
    if (!p.is_array() || p.size() < 4 || !p[0].is_number() || !p[1].is_number() ||
        !p[2].is_number() || !p[3].is_number()) {
      throw std::runtime_error(fmt::format("{} point {}: expected [x, y, z, width]", where, k));
    }
    polyline.push_back({Eigen::Vector3f(p[0].get<float>(), p[1].get<float>(), p[2].get<float>()),
                        p[3].get<float>()});
  }
  return polyline;
}

// Distance from x to the polyline's surface: distance to the centre line less half the width
// interpolated at the closest point.
float SurfaceDistance(const Eigen::Vector3f& x, const Polyline& polyline) {
  float best = std::numeric_limits<float>::max();
  for (size_t k = 0; k + 1 < polyline.size(); ++k) {
    const Eigen::Vector3f& a = polyline[k].position;
    const Eigen::Vector3f ab = polyline[k + 1].position - a;
    const float length2 = ab.squaredNorm();
    const float t = length2 > 0 ? std::clamp((x - a).dot(ab) / length2, 0.0f, 1.0f) : 0.0f;
    const float width = polyline[k].width + t * (polyline[k + 1].width - polyline[k].width);
    best = std::min(best, (a + t * ab - x).norm() - 0.5f * width);
  }
  return best;
}

}  // namespace

geometry::Mesh ReadPhenomenalPlant(const std::filesystem::path& folder) {
  const std::filesystem::path json_path = folder / "synthetic_plant.json";
  geometry::Mesh mesh = geometry::ReadMesh(folder / "synthetic_plant.ply");
  std::ifstream in(json_path);
  if (!in) throw std::runtime_error(fmt::format("{}: cannot open", json_path.string()));
  nlohmann::json skeleton;
  try {
    skeleton = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& error) {
    throw std::runtime_error(fmt::format("{}: {}", json_path.string(), error.what()));
  }
  if (!skeleton.contains("stem") || !skeleton.contains("leaf_polylines") ||
      !skeleton["leaf_polylines"].is_array()) {
    throw std::runtime_error(
        fmt::format("{}: expected keys 'stem' and 'leaf_polylines'", json_path.string()));
  }
  std::vector<Polyline> organs;  // stem first, then the leaves
  std::vector<int32_t> organ_labels;
  organs.push_back(ParsePolyline(skeleton["stem"], json_path.string() + ": stem"));
  organ_labels.push_back(geometry::labels::kStem);
  const nlohmann::json& leaves = skeleton["leaf_polylines"];
  for (size_t i = 0; i < leaves.size(); ++i) {
    organs.push_back(
        ParsePolyline(leaves[i], fmt::format("{}: leaf_polylines[{}]", json_path.string(), i)));
    organ_labels.push_back(geometry::labels::kLeafBase + static_cast<int32_t>(i));
  }
  mesh.face_labels.resize(mesh.faces.size());
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const Eigen::Vector3i& face = mesh.faces[f];
    const Eigen::Vector3f centroid =
        (mesh.vertices[face[0]] + mesh.vertices[face[1]] + mesh.vertices[face[2]]) / 3.0f;
    size_t nearest = 0;
    float nearest_distance = std::numeric_limits<float>::max();
    for (size_t o = 0; o < organs.size(); ++o) {
      const float distance = SurfaceDistance(centroid, organs[o]);
      if (distance < nearest_distance) {
        nearest_distance = distance;
        nearest = o;
      }
    }
    mesh.face_labels[f] = organ_labels[nearest];
  }
  return mesh;
}

}  // namespace avc::sim
