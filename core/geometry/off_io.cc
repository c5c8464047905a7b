// OFF reading (OFF, COFF, NOFF, STOFF and their combinations) and writing.

#include <cmath>

#include "core/geometry/mesh_io.h"
#include "core/geometry/mesh_io_internal.h"

namespace avc::geometry {
namespace mesh_io {
namespace {

struct OffLine {
  int number = 0;
  std::vector<std::string_view> tokens;
};

// Non-empty lines with '#' comments removed.
std::vector<OffLine> ContentLines(const std::string& bytes) {
  std::vector<OffLine> result;
  LineReader lines(bytes);
  std::string_view line;
  while (lines.Next(&line)) {
    std::vector<std::string_view> tokens = SplitTokens(line.substr(0, line.find('#')));
    if (!tokens.empty()) result.push_back({lines.line_number(), std::move(tokens)});
  }
  return result;
}

struct OffFlags {
  bool texture = false;
  bool color = false;
  bool normal = false;
};

uint8_t ColorChannel(std::string_view token, float value) {
  // Colours are integers 0..255 or floats 0..1 (written with a decimal point).
  const bool unit = token.find_first_of(".eE") != std::string_view::npos;
  const float scaled = unit ? value * 255.0f : value;
  return static_cast<uint8_t>(std::lround(std::clamp(scaled, 0.0f, 255.0f)));
}

}  // namespace

Mesh ReadOff(const std::filesystem::path& path, const std::string& bytes) {
  const std::vector<OffLine> lines = ContentLines(bytes);
  if (lines.empty()) Fail(path, "no content (only comments or blank lines)");
  std::string_view keyword = lines[0].tokens[0];
  if (keyword.size() < 3 || keyword.substr(keyword.size() - 3) != "OFF") {
    Fail(path, "line {}: not an OFF file (expected OFF, COFF, NOFF..., found '{}')",
         lines[0].number, keyword.substr(0, 40));
  }
  OffFlags flags;
  std::string_view prefix = keyword.substr(0, keyword.size() - 3);
  // Take one optional prefix off the front of what is left.
  auto take = [&prefix](std::string_view letters) {
    if (prefix.substr(0, letters.size()) != letters) return false;
    prefix.remove_prefix(letters.size());
    return true;
  };
  flags.texture = take("ST");
  flags.color = take("C");
  flags.normal = take("N");
  if (!prefix.empty()) {
    Fail(path, "line {}: unsupported OFF variant '{}'", lines[0].number, keyword.substr(0, 40));
  }
  // The counts follow the keyword on the same line or on the next one.
  std::vector<std::string_view> counts(lines[0].tokens.begin() + 1, lines[0].tokens.end());
  size_t next = 1;
  int counts_line = lines[0].number;
  if (counts.empty()) {
    if (lines.size() < 2) Fail(path, "missing vertex and face counts");
    counts = lines[1].tokens;
    counts_line = lines[1].number;
    next = 2;
  }
  int64_t vertex_count = 0;
  int64_t face_count = 0;
  if (counts.size() < 2 || !ParseInt(counts[0], &vertex_count) ||
      !ParseInt(counts[1], &face_count) || vertex_count < 0 || face_count < 0) {
    Fail(path, "line {}: expected '<vertices> <faces> <edges>'", counts_line);
  }
  const size_t needed = next + static_cast<size_t>(vertex_count) + static_cast<size_t>(face_count);
  if (lines.size() < needed) {
    Fail(path, "expected {} vertices and {} faces but the file ends after {} of them", vertex_count,
         face_count, lines.size() - next);
  }
  Mesh mesh;
  mesh.vertices.reserve(vertex_count);
  const size_t coordinates = 3 + (flags.normal ? 3 : 0);
  for (int64_t i = 0; i < vertex_count; ++i) {
    const OffLine& line = lines[next++];
    const size_t minimum = coordinates + (flags.color ? 3 : 0) + (flags.texture ? 2 : 0);
    if (line.tokens.size() < minimum) {
      Fail(path, "line {}: vertex {} has {} numbers, expected at least {}", line.number, i,
           line.tokens.size(), minimum);
    }
    std::vector<float> numbers(line.tokens.size());
    for (size_t k = 0; k < line.tokens.size(); ++k) {
      if (!ParseFloat(line.tokens[k], &numbers[k])) {
        Fail(path, "line {}: vertex {}: '{}' is not a number", line.number, i,
             line.tokens[k].substr(0, 40));
      }
    }
    mesh.vertices.emplace_back(numbers[0], numbers[1], numbers[2]);
    size_t k = coordinates;
    if (flags.color) {
      mesh.colors.emplace_back(ColorChannel(line.tokens[k], numbers[k]),
                               ColorChannel(line.tokens[k + 1], numbers[k + 1]),
                               ColorChannel(line.tokens[k + 2], numbers[k + 2]));
      // Alpha is optional; texture coordinates, if any, are the last two numbers.
    }
    if (flags.texture) {
      k = numbers.size() - 2;
      mesh.uvs.emplace_back(numbers[k], numbers[k + 1]);
    }
  }
  std::vector<int> corners;
  for (int64_t i = 0; i < face_count; ++i) {
    const OffLine& line = lines[next++];
    int64_t size = 0;
    if (!ParseInt(line.tokens[0], &size) || size < 3 ||
        line.tokens.size() < static_cast<size_t>(size) + 1) {
      Fail(path, "line {}: face {} is not '<n >= 3> <n vertex indices>'", line.number, i);
    }
    corners.clear();
    for (int64_t k = 1; k <= size; ++k) {
      int64_t index = 0;
      if (!ParseInt(line.tokens[k], &index)) {
        Fail(path, "line {}: face {}: '{}' is not an index", line.number, i,
             line.tokens[k].substr(0, 40));
      }
      if (index < 0 || index >= vertex_count) {
        Fail(path, "line {}: face {} refers to vertex {} of {}", line.number, i, index,
             vertex_count);
      }
      corners.push_back(static_cast<int>(index));
    }
    AppendFan(corners, &mesh);
  }
  return mesh;
}

}  // namespace mesh_io

void WriteMeshOff(const std::filesystem::path& path, const Mesh& mesh) {
  mesh_io::CheckWritable(path, mesh);
  std::string text = mesh.colors.empty() ? "OFF\n" : "COFF\n";
  auto out = std::back_inserter(text);
  fmt::format_to(out, "{} {} 0\n", mesh.vertices.size(), mesh.faces.size());
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Eigen::Vector3f& p = mesh.vertices[i];
    fmt::format_to(out, "{} {} {}", p.x(), p.y(), p.z());
    if (!mesh.colors.empty()) {
      fmt::format_to(out, " {} {} {} 255", mesh.colors[i][0], mesh.colors[i][1], mesh.colors[i][2]);
    }
    text.push_back('\n');
  }
  for (const Eigen::Vector3i& f : mesh.faces) fmt::format_to(out, "3 {} {} {}\n", f[0], f[1], f[2]);
  mesh_io::WriteWholeFile(path, text);
}

}  // namespace avc::geometry
