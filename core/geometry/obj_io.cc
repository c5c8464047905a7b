// Wavefront OBJ reading and writing (geometry, per-vertex colours and texture coordinates).

#include <cmath>
#include <map>
#include <utility>

#include "core/geometry/mesh_io.h"
#include "core/geometry/mesh_io_internal.h"

namespace avc::geometry {
namespace mesh_io {
namespace {

uint8_t ColorFromUnit(float value) {
  return static_cast<uint8_t>(std::lround(std::clamp(value * 255.0f, 0.0f, 255.0f)));
}

// Resolves a 1-based or negative (relative) OBJ index against count items; -1 when invalid.
int64_t Resolve(int64_t index, size_t count) {
  if (index > 0 && static_cast<size_t>(index) <= count) return index - 1;
  if (index < 0 && static_cast<size_t>(-index) <= count) return static_cast<int64_t>(count) + index;
  return -1;
}

struct ObjState {
  std::vector<Eigen::Vector3f> positions;
  std::vector<Eigen::Matrix<uint8_t, 3, 1>> colors;
  std::vector<Eigen::Vector2f> texcoords;
  std::vector<int> vertex_texcoord;           // per file vertex: its texcoord, -1 when not yet used
  std::map<std::pair<int, int>, int> copies;  // (vertex, texcoord) -> copy number
  std::vector<std::pair<int, int>> copy_sources;
  bool used_texcoords = false;
  // Corners of all faces; copies are stored as -(copy number + 1) until the end.
  std::vector<Eigen::Vector3i> faces;
};

// The corner's vertex, or a copy of it when the vertex already carries another texcoord.
int CornerVertex(int vertex, int texcoord, ObjState* state) {
  if (texcoord < 0) return vertex;
  state->used_texcoords = true;
  int& assigned = state->vertex_texcoord[vertex];
  if (assigned < 0 || assigned == texcoord) {
    assigned = texcoord;
    return vertex;
  }
  const auto [it, inserted] =
      state->copies.try_emplace({vertex, texcoord}, static_cast<int>(state->copy_sources.size()));
  if (inserted) state->copy_sources.emplace_back(vertex, texcoord);
  return -(it->second + 1);
}

void ParseFace(const std::filesystem::path& path, int line, size_t face_number,
               const std::vector<std::string_view>& tokens, ObjState* state) {
  if (tokens.size() < 4) Fail(path, "line {}: face {} has fewer than 3 corners", line, face_number);
  std::vector<int> corners;
  for (size_t k = 1; k < tokens.size(); ++k) {
    const std::string_view corner = tokens[k];
    const size_t slash = corner.find('/');
    int64_t v = 0;
    if (!ParseInt(corner.substr(0, slash), &v)) {
      Fail(path, "line {}: bad face corner '{}'", line, corner);
    }
    const int64_t vertex = Resolve(v, state->positions.size());
    if (vertex < 0) {
      Fail(path, "line {}: face {} refers to vertex {} of {}", line, face_number, v,
           state->positions.size());
    }
    int64_t texcoord = -1;
    if (slash != std::string_view::npos) {
      const std::string_view rest = corner.substr(slash + 1);
      const std::string_view vt_text = rest.substr(0, rest.find('/'));
      if (!vt_text.empty()) {
        int64_t vt = 0;
        if (!ParseInt(vt_text, &vt)) Fail(path, "line {}: bad face corner '{}'", line, corner);
        texcoord = Resolve(vt, state->texcoords.size());
        if (texcoord < 0) {
          Fail(path, "line {}: face {} refers to texture coordinate {} of {}", line, face_number,
               vt, state->texcoords.size());
        }
      }
    }
    corners.push_back(CornerVertex(static_cast<int>(vertex), static_cast<int>(texcoord), state));
  }
  for (size_t k = 1; k + 1 < corners.size(); ++k) {
    state->faces.emplace_back(corners[0], corners[k], corners[k + 1]);
  }
}

std::vector<float> ParseNumbers(const std::filesystem::path& path, int line,
                                const std::vector<std::string_view>& tokens) {
  std::vector<float> numbers;
  for (size_t k = 1; k < tokens.size(); ++k) {
    float value = 0;
    if (!ParseFloat(tokens[k], &value)) {
      Fail(path, "line {}: '{}' is not a number", line, tokens[k].substr(0, 40));
    }
    numbers.push_back(value);
  }
  return numbers;
}

Mesh AssembleMesh(ObjState state) {
  Mesh mesh;
  const int file_vertices = static_cast<int>(state.positions.size());
  mesh.vertices = std::move(state.positions);
  const bool colored = !state.colors.empty();
  if (colored) mesh.colors = std::move(state.colors);
  if (state.used_texcoords) {
    mesh.uvs.assign(mesh.vertices.size(), Eigen::Vector2f::Zero());
    for (int i = 0; i < file_vertices; ++i) {
      if (state.vertex_texcoord[i] >= 0) mesh.uvs[i] = state.texcoords[state.vertex_texcoord[i]];
    }
  }
  for (const auto& [vertex, texcoord] : state.copy_sources) {
    mesh.vertices.push_back(mesh.vertices[vertex]);
    if (colored) mesh.colors.push_back(mesh.colors[vertex]);
    mesh.uvs.push_back(state.texcoords[texcoord]);
  }
  for (Eigen::Vector3i& face : state.faces) {
    for (int k = 0; k < 3; ++k) {
      if (face[k] < 0) face[k] = file_vertices - face[k] - 1;
    }
  }
  mesh.faces = std::move(state.faces);
  return mesh;
}

}  // namespace

Mesh ReadObj(const std::filesystem::path& path, const std::string& bytes) {
  ObjState state;
  LineReader lines(bytes);
  std::string_view line;
  size_t face_number = 0;
  while (lines.Next(&line)) {
    const int n = lines.line_number();
    const std::vector<std::string_view> tokens = SplitTokens(line.substr(0, line.find('#')));
    if (tokens.empty()) continue;
    const std::string_view keyword = tokens[0];
    if (keyword == "v") {
      const std::vector<float> numbers = ParseNumbers(path, n, tokens);
      if (numbers.size() < 3) Fail(path, "line {}: vertex needs x y z", n);
      state.positions.emplace_back(numbers[0], numbers[1], numbers[2]);
      state.vertex_texcoord.push_back(-1);
      // "v x y z r g b" carries a colour; every vertex must then have one.
      const bool has_color = numbers.size() == 6 || numbers.size() == 7;
      const size_t before = state.positions.size() - 1;
      if (before > 0 && has_color != (state.colors.size() == before)) {
        Fail(path, "line {}: some vertices have colours and others not", n);
      }
      if (has_color) {
        const size_t c = numbers.size() - 3;
        state.colors.emplace_back(ColorFromUnit(numbers[c]), ColorFromUnit(numbers[c + 1]),
                                  ColorFromUnit(numbers[c + 2]));
      }
    } else if (keyword == "vt") {
      const std::vector<float> numbers = ParseNumbers(path, n, tokens);
      if (numbers.empty()) Fail(path, "line {}: texture coordinate needs u [v]", n);
      state.texcoords.emplace_back(numbers[0], numbers.size() > 1 ? numbers[1] : 0.0f);
    } else if (keyword == "f") {
      ParseFace(path, n, face_number++, tokens, &state);
    }
    // Normals, groups, materials, smoothing and other statements do not affect the mesh.
  }
  if (state.positions.empty()) Fail(path, "no vertices (not an OBJ file?)");
  return AssembleMesh(std::move(state));
}

}  // namespace mesh_io

void WriteMeshObj(const std::filesystem::path& path, const Mesh& mesh) {
  mesh_io::CheckWritable(path, mesh);
  std::string text = "# avc mesh\n";
  auto out = std::back_inserter(text);
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Eigen::Vector3f& p = mesh.vertices[i];
    fmt::format_to(out, "v {} {} {}", p.x(), p.y(), p.z());
    if (!mesh.colors.empty()) {
      for (int k = 0; k < 3; ++k) fmt::format_to(out, " {}", mesh.colors[i][k] / 255.0f);
    }
    text.push_back('\n');
  }
  for (const Eigen::Vector2f& uv : mesh.uvs) fmt::format_to(out, "vt {} {}\n", uv.x(), uv.y());
  for (const Eigen::Vector3i& f : mesh.faces) {
    if (mesh.uvs.empty()) {
      fmt::format_to(out, "f {} {} {}\n", f[0] + 1, f[1] + 1, f[2] + 1);
    } else {
      fmt::format_to(out, "f {0}/{0} {1}/{1} {2}/{2}\n", f[0] + 1, f[1] + 1, f[2] + 1);
    }
  }
  mesh_io::WriteWholeFile(path, text);
}

}  // namespace avc::geometry
