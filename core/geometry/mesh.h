#pragma once

// A triangle mesh as the whole system passes it around: ground-truth plants, reconstructed
// surfaces, loaded files. Optional per-vertex and per-face attributes are either empty or exactly
// as long as vertices / faces.

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace avc::geometry {

// Organ labels of ground-truth faces and label images. Leaves are kLeafBase + leaf index.
namespace labels {
inline constexpr int32_t kBackground = 0;
inline constexpr int32_t kPot = 1;
inline constexpr int32_t kSoil = 2;
inline constexpr int32_t kStem = 3;
inline constexpr int32_t kPetiole = 4;
inline constexpr int32_t kTarget = 5;  // a calibration board, not part of any plant
inline constexpr int32_t kLeafBase = 100;
inline bool IsLeaf(int32_t label) { return label >= kLeafBase; }
// "pot", "stem", "leaf 3", ... for reports.
std::string Name(int32_t label);
}  // namespace labels

struct Mesh {
  std::vector<Eigen::Vector3f> vertices;  // metres
  std::vector<Eigen::Vector3i> faces;     // counter-clockwise seen from the front side

  // Optional attributes.
  std::vector<Eigen::Vector2f> uvs;                  // per vertex: texture coordinates
  std::vector<Eigen::Matrix<uint8_t, 3, 1>> colors;  // per vertex: RGB
  std::vector<int32_t> face_labels;                  // per face: labels:: organ
  std::vector<int32_t> face_materials;               // per face: index into the scene's materials

  size_t num_vertices() const { return vertices.size(); }
  size_t num_faces() const { return faces.size(); }
  // Empty when consistent, else a sentence naming the first problem (index out of range,
  // attribute of the wrong length, non-finite vertex).
  std::string Validate() const;
  // Appends other (indices shifted); attributes present in only one side are filled with
  // defaults (uv 0, colour 128 grey, label kBackground, material 0) so lengths stay right.
  void Append(const Mesh& other);
};

// Sum of triangle areas (m^2).
// Area of one face (m^2).
double FaceArea(const Mesh& mesh, const Eigen::Vector3i& face);
double SurfaceArea(const Mesh& mesh);
// Axis-aligned bounds; both zero for an empty mesh.
void Bounds(const Mesh& mesh, Eigen::Vector3f* min, Eigen::Vector3f* max);

}  // namespace avc::geometry
