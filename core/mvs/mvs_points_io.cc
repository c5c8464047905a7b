#include "core/mvs/mvs_points_io.h"

#include <fmt/format.h>

#include <stdexcept>

#include "core/geometry/mesh_io_internal.h"
#include "core/geometry/ply_table.h"
#include "core/geometry/ply_writer.h"

namespace avc::mvs {
namespace ply = geometry::ply;

std::string MvsPointsToPly(const MvsPoints& points, bool binary) {
  if (const std::string problem = points.Validate(); !problem.empty()) {
    throw std::invalid_argument("cannot write inconsistent MVS points: " + problem);
  }
  ply::Writer writer(binary);
  writer.AddComment("avc multi-view stereo points: view_indices index the scan's cameras");
  writer.AddElement("vertex", points.size());
  for (const char* name : {"x", "y", "z", "nx", "ny", "nz"}) {
    writer.AddProperty(ply::Type::kFloat32, name);
  }
  for (const char* name : {"red", "green", "blue"}) writer.AddProperty(ply::Type::kUint8, name);
  writer.AddProperty(ply::Type::kFloat32, "confidence");
  writer.AddListProperty(ply::Type::kUint8, ply::Type::kInt32, "view_indices");
  writer.EndHeader();
  const auto& cloud = points.cloud;
  for (size_t i = 0; i < points.size(); ++i) {
    for (int k = 0; k < 3; ++k) writer.Put(cloud.positions[i][k]);
    for (int k = 0; k < 3; ++k) writer.Put(cloud.normals[i][k]);
    for (int k = 0; k < 3; ++k) writer.Put(cloud.colors[i][k]);
    writer.Put(points.confidence[i]);
    if (points.views[i].size() > 255) {
      throw std::invalid_argument(
          fmt::format("point {} is seen by {} views; at most 255 fit", i, points.views[i].size()));
    }
    writer.Put(static_cast<uint8_t>(points.views[i].size()));
    for (uint32_t view : points.views[i]) writer.Put(static_cast<int32_t>(view));
    writer.EndRecord();
  }
  return writer.TakeBytes();
}

void WriteMvsPointsPly(const std::filesystem::path& path, const MvsPoints& points, bool binary) {
  geometry::mesh_io::WriteWholeFile(path, MvsPointsToPly(points, binary));
}

MvsPoints ReadMvsPointsPly(const std::filesystem::path& path) {
  const std::string bytes = geometry::mesh_io::ReadWholeFile(path);
  const std::string file = path.string();
  ply::Table table = ply::ParseHeader(file, bytes);
  const ply::Element* vertex = table.Find("vertex");
  if (vertex == nullptr) geometry::mesh_io::Fail(path, "no vertex element");
  const auto xyz = ply::FindTriple(*vertex, {"x"}, {"y"}, {"z"});
  if (xyz[0] < 0) geometry::mesh_io::Fail(path, "the vertex element has no x, y and z");
  const auto normal = ply::FindTriple(*vertex, {"nx"}, {"ny"}, {"nz"});
  const int confidence = vertex->FindScalar({"confidence"});
  const int views = vertex->FindList({"view_indices"});
  ply::ReadBody(file, bytes, {"vertex"}, /*read_whole_body=*/false, &table);

  MvsPoints points;
  const size_t n = vertex->count;
  points.cloud.positions = ply::Vector3fColumns(*vertex, xyz);
  points.cloud.normals = normal[0] >= 0 ? ply::Vector3fColumns(*vertex, normal)
                                        : std::vector<Eigen::Vector3f>(n, Eigen::Vector3f::Zero());
  points.cloud.colors = ply::Colors(*vertex);
  if (points.cloud.colors.empty()) points.cloud.colors.assign(n, {0, 0, 0});
  points.confidence.assign(n, 1.0f);
  points.views.resize(n);
  for (size_t i = 0; i < n; ++i) {
    if (confidence >= 0) points.confidence[i] = static_cast<float>(vertex->columns[confidence][i]);
    if (views >= 0) {
      const ply::Column& column = vertex->columns[views];
      for (size_t j = column.ListBegin(i); j < column.ListEnd(i); ++j) {
        const double view = column[j];
        if (view < 0) geometry::mesh_io::Fail(path, "vertex {}: negative view index", i);
        points.views[i].push_back(static_cast<uint32_t>(view));
      }
    }
  }
  if (const std::string problem = points.Validate(); !problem.empty()) {
    geometry::mesh_io::Fail(path, "{}", problem);
  }
  return points;
}

}  // namespace avc::mvs
