#include "core/geometry/point_cloud_io.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/geometry/mesh_io.h"
#include "core/geometry/mesh_io_internal.h"
#include "core/geometry/ply_table.h"
#include "core/geometry/ply_writer.h"

namespace avc::geometry {
namespace {

std::runtime_error FileError(const std::filesystem::path& path, const std::string& what) {
  return std::runtime_error(fmt::format("{}: {}", path.string(), what));
}

std::string LowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::ifstream OpenForReading(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, std::string("cannot open for reading: ") + std::strerror(errno));
  return in;
}

std::string ReadAll(const std::filesystem::path& path) {
  std::string bytes;
  if (const std::string why = mesh_io::ReadFileBytes(path, &bytes); !why.empty()) {
    throw FileError(path, "cannot read: " + why);
  }
  return bytes;
}

// ---- PLY --------------------------------------------------------------------------------------

PointCloud ReadPlyCloud(const std::filesystem::path& path) {
  const std::string bytes = ReadAll(path);
  const std::string file = path.string();
  ply::Table table = ply::ParseHeader(file, bytes);
  const ply::Element* vertex = table.Find("vertex");
  if (vertex == nullptr) throw FileError(path, "no vertex element");
  const std::array<int, 3> xyz = ply::FindTriple(*vertex, {"x"}, {"y"}, {"z"});
  if (xyz[0] < 0) throw FileError(path, "the vertex element has no x, y and z properties");
  const std::array<int, 3> normal = ply::FindTriple(*vertex, {"nx"}, {"ny"}, {"nz"});
  // Elements after the vertices (a mesh's faces) are not read at all.
  ply::ReadBody(file, bytes, {"vertex"}, /*read_whole_body=*/false, &table);

  PointCloud cloud;
  cloud.positions = ply::Vector3fColumns(*vertex, xyz);
  for (size_t i = 0; i < cloud.positions.size(); ++i) {
    if (!cloud.positions[i].allFinite()) {
      throw FileError(path, fmt::format("vertex {} is not finite", i));
    }
  }
  if (normal[0] >= 0) cloud.normals = ply::Vector3fColumns(*vertex, normal);
  cloud.colors = ply::Colors(*vertex);
  return cloud;
}

// The header of a PLY file, up to its end_header line, without reading the body.
std::string ReadPlyHeaderText(const std::filesystem::path& path) {
  std::ifstream in = OpenForReading(path);
  std::string text;
  std::string line;
  while (std::getline(in, line)) {
    text += line + "\n";
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
    if (line == "end_header") break;
  }
  return text;
}

// ---- XYZ --------------------------------------------------------------------------------------

PointCloud ReadXyzCloud(const std::filesystem::path& path) {
  std::ifstream in = OpenForReading(path);
  PointCloud cloud;
  std::string line;
  size_t columns = 0;
  std::vector<float> values;
  for (size_t line_number = 1; std::getline(in, line); ++line_number) {
    values.clear();
    const char* cursor = line.data();
    const char* end = line.data() + line.size();
    while (true) {
      while (cursor < end && std::isspace(static_cast<unsigned char>(*cursor))) ++cursor;
      if (cursor >= end || *cursor == '#') break;
      const char* token_end = cursor;
      while (token_end < end && !std::isspace(static_cast<unsigned char>(*token_end))) ++token_end;
      float value = 0;  // parsed as float: shortest decimal forms round-trip exactly
      const auto [stop, error] = std::from_chars(cursor, token_end, value);
      if (error != std::errc() || stop != token_end) {
        throw FileError(path, fmt::format("line {}: '{}' is not a number", line_number,
                                          std::string(cursor, token_end)));
      }
      values.push_back(value);
      cursor = token_end;
    }
    if (values.empty()) continue;
    if (columns == 0) columns = values.size();
    if (values.size() != columns || (columns != 3 && columns != 6)) {
      throw FileError(path, fmt::format("line {}: {} numbers; expected 3 (x y z) or 6 "
                                        "(x y z nx ny nz) on every line{}",
                                        line_number, values.size(),
                                        columns == values.size()
                                            ? std::string()
                                            : fmt::format(" (the first line has {})", columns)));
    }
    const Eigen::Vector3f position(values[0], values[1], values[2]);
    if (!position.allFinite()) {
      throw FileError(path, fmt::format("line {}: the point is not finite", line_number));
    }
    cloud.positions.push_back(position);
    if (columns == 6) {
      cloud.normals.emplace_back(values[3], values[4], values[5]);
    }
  }
  return cloud;
}

}  // namespace

PointCloud ReadPointCloud(const std::filesystem::path& path) {
  const std::string ext = LowerExtension(path);
  if (!std::filesystem::exists(path)) throw FileError(path, "no such file");
  if (ext == ".ply") return ReadPlyCloud(path);
  if (ext == ".xyz") return ReadXyzCloud(path);
  if (ext == ".obj" || ext == ".off") {
    Mesh mesh = ReadMesh(path);
    PointCloud cloud;
    cloud.positions = std::move(mesh.vertices);
    cloud.colors = std::move(mesh.colors);
    return cloud;
  }
  throw FileError(path, "unknown point cloud format (expected .ply, .xyz, .obj or .off)");
}

bool PlyHasFaces(const std::filesystem::path& path) {
  const ply::Table header = ply::ParseHeader(path.string(), ReadPlyHeaderText(path));
  return std::any_of(header.elements.begin(), header.elements.end(),
                     [](const ply::Element& e) { return e.name == "face" && e.count > 0; });
}

void WritePointCloudPly(const std::filesystem::path& path, const PointCloud& cloud, bool binary) {
  if (const std::string problem = cloud.Validate(); !problem.empty()) {
    throw FileError(path, "cannot write an inconsistent point cloud: " + problem);
  }
  const bool has_normals = !cloud.normals.empty();
  const bool has_colours = !cloud.colors.empty();
  ply::Writer ply(binary);
  ply.AddElement("vertex", cloud.size());
  for (const char* name : {"x", "y", "z"}) ply.AddProperty(ply::Type::kFloat32, name);
  if (has_normals) {
    for (const char* name : {"nx", "ny", "nz"}) ply.AddProperty(ply::Type::kFloat32, name);
  }
  if (has_colours) {
    for (const char* name : {"red", "green", "blue"}) ply.AddProperty(ply::Type::kUint8, name);
  }
  ply.EndHeader();
  for (size_t i = 0; i < cloud.size(); ++i) {
    for (int k = 0; k < 3; ++k) ply.Put(cloud.positions[i][k]);
    if (has_normals) {
      for (int k = 0; k < 3; ++k) ply.Put(cloud.normals[i][k]);
    }
    if (has_colours) {
      for (int k = 0; k < 3; ++k) ply.Put(cloud.colors[i][k]);
    }
    ply.EndRecord();
  }
  if (const std::string why = mesh_io::WriteFileBytes(path, ply.TakeBytes()); !why.empty()) {
    throw FileError(path, "cannot write: " + why);
  }
}

}  // namespace avc::geometry
