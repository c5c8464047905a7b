// Meshes from and to PLY (ascii, binary little and big endian), on the shared PLY table reader
// and writer.

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "core/geometry/mesh_io.h"
#include "core/geometry/mesh_io_internal.h"
#include "core/geometry/ply_table.h"
#include "core/geometry/ply_writer.h"

namespace avc::geometry {
namespace mesh_io {
namespace {

using ply::Type;

// An index or label stored in the file, refused unless it is a whole number in int32 range.
int32_t WholeNumber(const std::filesystem::path& path, const ply::Element& element, size_t index,
                    int property, double value) {
  if (!(std::abs(value) <= 2147483647.0) || value != std::floor(value)) {
    Fail(path, "{} {} of {}: {} is {}, not a whole number", element.name, index, element.count,
         element.properties[property].name, value);
  }
  return static_cast<int32_t>(value);
}

// Checks the layout before the body is read, so a file we cannot use fails fast.
struct Layout {
  std::array<int, 3> xyz = {-1, -1, -1};
  int u = -1, v = -1;
  int corners = -1, label = -1, material = -1;
};

Layout FindLayout(const std::filesystem::path& path, const ply::Table& table) {
  Layout layout;
  if (const ply::Element* vertex = table.Find("vertex")) {
    layout.xyz = ply::FindTriple(*vertex, {"x"}, {"y"}, {"z"});
    if (layout.xyz[0] < 0) Fail(path, "vertex element lacks x, y or z");
    layout.u = vertex->FindScalar({"u", "s", "texture_u", "texture_s"});
    layout.v = vertex->FindScalar({"v", "t", "texture_v", "texture_t"});
    if (layout.u < 0 || layout.v < 0) layout.u = layout.v = -1;
  }
  if (const ply::Element* face = table.Find("face")) {
    layout.corners = face->FindList({"vertex_indices", "vertex_index"});
    if (layout.corners < 0) Fail(path, "face element has no vertex_indices list");
    layout.label = face->FindScalar({"label"});
    layout.material = face->FindScalar({"material"});
  }
  return layout;
}

void ReadVertices(const ply::Element& vertex, const Layout& layout, Mesh* mesh) {
  mesh->vertices = ply::Vector3fColumns(vertex, layout.xyz);
  mesh->colors = ply::Colors(vertex);
  if (layout.u < 0) return;
  const ply::Column& u = vertex.columns[layout.u];
  const ply::Column& v = vertex.columns[layout.v];
  mesh->uvs.resize(u.size());
  for (size_t i = 0; i < u.size(); ++i) {
    mesh->uvs[i] = Eigen::Vector2f(static_cast<float>(u[i]), static_cast<float>(v[i]));
  }
}

// Polygons are fanned into triangles; each triangle gets its polygon's label and material.
void ReadFaces(const std::filesystem::path& path, const ply::Element& face, const Layout& layout,
               size_t vertex_count, Mesh* mesh) {
  mesh->faces.reserve(face.count);
  std::vector<int> corners;
  for (size_t i = 0; i < face.count; ++i) {
    corners.clear();
    const ply::Column& list = face.columns[layout.corners];
    for (size_t k = list.ListBegin(i); k < list.ListEnd(i); ++k) {
      corners.push_back(WholeNumber(path, face, i, layout.corners, list[k]));
    }
    if (corners.size() < 3) {
      Fail(path, "face {} has {} corners (at least 3 needed)", i, corners.size());
    }
    for (int corner : corners) {
      if (corner < 0 || static_cast<size_t>(corner) >= vertex_count) {
        Fail(path, "face {} refers to vertex {} of {}", i, corner, vertex_count);
      }
    }
    AppendFan(corners, mesh);
    const size_t triangles = corners.size() - 2;
    if (layout.label >= 0) {
      const double label = face.columns[layout.label][i];
      mesh->face_labels.insert(mesh->face_labels.end(), triangles,
                               WholeNumber(path, face, i, layout.label, label));
    }
    if (layout.material >= 0) {
      const double material = face.columns[layout.material][i];
      mesh->face_materials.insert(mesh->face_materials.end(), triangles,
                                  WholeNumber(path, face, i, layout.material, material));
    }
  }
}

std::string PlyBytes(const Mesh& mesh, bool binary) {
  ply::Writer ply(binary);
  ply.AddComment("avc mesh");
  ply.AddElement("vertex", mesh.vertices.size());
  for (const char* name : {"x", "y", "z"}) ply.AddProperty(Type::kFloat32, name);
  if (!mesh.colors.empty()) {
    for (const char* name : {"red", "green", "blue"}) ply.AddProperty(Type::kUint8, name);
  }
  if (!mesh.uvs.empty()) {
    for (const char* name : {"u", "v"}) ply.AddProperty(Type::kFloat32, name);
  }
  ply.AddElement("face", mesh.faces.size());
  ply.AddListProperty(Type::kUint8, Type::kInt32, "vertex_indices");
  if (!mesh.face_labels.empty()) ply.AddProperty(Type::kInt32, "label");
  if (!mesh.face_materials.empty()) ply.AddProperty(Type::kInt32, "material");
  ply.EndHeader();
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    for (int k = 0; k < 3; ++k) ply.Put(mesh.vertices[i][k]);
    if (!mesh.colors.empty()) {
      for (int k = 0; k < 3; ++k) ply.Put(mesh.colors[i][k]);
    }
    if (!mesh.uvs.empty()) {
      for (int k = 0; k < 2; ++k) ply.Put(mesh.uvs[i][k]);
    }
    ply.EndRecord();
  }
  for (size_t i = 0; i < mesh.faces.size(); ++i) {
    ply.Put(uint8_t{3});
    for (int k = 0; k < 3; ++k) ply.Put(mesh.faces[i][k]);
    if (!mesh.face_labels.empty()) ply.Put(mesh.face_labels[i]);
    if (!mesh.face_materials.empty()) ply.Put(mesh.face_materials[i]);
    ply.EndRecord();
  }
  return ply.TakeBytes();
}

}  // namespace

Mesh ReadPly(const std::filesystem::path& path, const std::string& bytes) {
  const std::string file = path.filename().string();
  ply::Table table = ply::ParseHeader(file, bytes);
  const Layout layout = FindLayout(path, table);
  ply::ReadBody(file, bytes, {"vertex", "face"}, /*read_whole_body=*/true, &table);
  Mesh mesh;
  size_t vertex_count = 0;
  if (const ply::Element* vertex = table.Find("vertex")) {
    ReadVertices(*vertex, layout, &mesh);
    vertex_count = vertex->count;
  }
  if (const ply::Element* face = table.Find("face")) {
    ReadFaces(path, *face, layout, vertex_count, &mesh);
  }
  return mesh;
}

}  // namespace mesh_io

void WriteMeshPly(const std::filesystem::path& path, const Mesh& mesh, bool binary) {
  mesh_io::CheckWritable(path, mesh);
  mesh_io::WriteWholeFile(path, mesh_io::PlyBytes(mesh, binary));
}

}  // namespace avc::geometry
