#include "core/geometry/mesh.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>

namespace avc::geometry {

std::string labels::Name(int32_t label) {
  switch (label) {
    case kBackground:
      return "background";
    case kPot:
      return "pot";
    case kSoil:
      return "soil";
    case kStem:
      return "stem";
    case kPetiole:
      return "petiole";
    case kTarget:
      return "target";
    default:
      break;
  }
  if (IsLeaf(label)) return fmt::format("leaf {}", label - kLeafBase);
  return fmt::format("label {}", label);
}

std::string Mesh::Validate() const {
  const size_t nv = vertices.size();
  const size_t nf = faces.size();
  auto wrong_length = [](const char* name, size_t size, size_t expected, const char* per) {
    return fmt::format("{} has {} entries, expected 0 or one per {} ({})", name, size, per,
                       expected);
  };
  if (!uvs.empty() && uvs.size() != nv) return wrong_length("uvs", uvs.size(), nv, "vertex");
  if (!colors.empty() && colors.size() != nv) {
    return wrong_length("colors", colors.size(), nv, "vertex");
  }
  if (!face_labels.empty() && face_labels.size() != nf) {
    return wrong_length("face_labels", face_labels.size(), nf, "face");
  }
  if (!face_materials.empty() && face_materials.size() != nf) {
    return wrong_length("face_materials", face_materials.size(), nf, "face");
  }
  for (size_t i = 0; i < nv; ++i) {
    if (!vertices[i].allFinite()) return fmt::format("vertex {} is not finite", i);
  }
  for (size_t i = 0; i < nf; ++i) {
    for (int k = 0; k < 3; ++k) {
      if (faces[i][k] < 0 || static_cast<size_t>(faces[i][k]) >= nv) {
        return fmt::format("face {} refers to vertex {} of {}", i, faces[i][k], nv);
      }
    }
  }
  return {};
}

namespace {

template <class T>
void AppendAttribute(std::vector<T>& mine, size_t my_count, const std::vector<T>& theirs,
                     size_t their_count, const T& fill) {
  if (mine.empty() && theirs.empty()) return;
  if (mine.empty()) mine.assign(my_count, fill);
  if (theirs.empty()) {
    mine.insert(mine.end(), their_count, fill);
  } else {
    mine.insert(mine.end(), theirs.begin(), theirs.end());
  }
}

}  // namespace

void Mesh::Append(const Mesh& other) {
  const size_t nv = vertices.size();
  const size_t nf = faces.size();
  AppendAttribute(uvs, nv, other.uvs, other.vertices.size(), Eigen::Vector2f(0, 0));
  AppendAttribute(colors, nv, other.colors, other.vertices.size(),
                  Eigen::Matrix<uint8_t, 3, 1>(128, 128, 128));
  AppendAttribute(face_labels, nf, other.face_labels, other.faces.size(), labels::kBackground);
  AppendAttribute(face_materials, nf, other.face_materials, other.faces.size(), 0);
  vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
  const Eigen::Vector3i offset = Eigen::Vector3i::Constant(static_cast<int>(nv));
  for (const Eigen::Vector3i& face : other.faces) faces.push_back(face + offset);
}

double FaceArea(const Mesh& mesh, const Eigen::Vector3i& face) {
  const Eigen::Vector3d a = mesh.vertices[face[0]].cast<double>();
  const Eigen::Vector3d b = mesh.vertices[face[1]].cast<double>();
  const Eigen::Vector3d c = mesh.vertices[face[2]].cast<double>();
  return 0.5 * (b - a).cross(c - a).norm();
}

double SurfaceArea(const Mesh& mesh) {
  double area = 0;
  for (const Eigen::Vector3i& f : mesh.faces) area += FaceArea(mesh, f);
  return area;
}

void Bounds(const Mesh& mesh, Eigen::Vector3f* min, Eigen::Vector3f* max) {
  if (mesh.vertices.empty()) {
    *min = *max = Eigen::Vector3f::Zero();
    return;
  }
  *min = *max = mesh.vertices.front();
  for (const Eigen::Vector3f& v : mesh.vertices) {
    *min = min->cwiseMin(v);
    *max = max->cwiseMax(v);
  }
}

}  // namespace avc::geometry
