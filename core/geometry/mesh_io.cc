#include "core/geometry/mesh_io.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>

#include "core/geometry/mesh_io_internal.h"

namespace avc::geometry {
namespace mesh_io {

std::string ReadWholeFile(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    Fail(path, "no such file ({})", path.string());
  std::string bytes;
  if (const std::string why = ReadFileBytes(path, &bytes); !why.empty()) {
    Fail(path, "cannot read ({}): {}", path.string(), why);
  }
  if (bytes.empty()) Fail(path, "empty file");
  return bytes;
}

void WriteWholeFile(const std::filesystem::path& path, const std::string& bytes) {
  if (const std::string why = WriteFileBytes(path, bytes); !why.empty()) {
    Fail(path, "cannot write ({}): {}", path.string(), why);
  }
}

std::string ReadFileBytes(const std::filesystem::path& path, std::string* bytes) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) return std::strerror(EISDIR);
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return std::strerror(errno);
  const std::streamoff size = in.tellg();
  if (size < 0) return "not a file of known size";
  bytes->resize(static_cast<size_t>(size));
  in.seekg(0);
  in.read(bytes->data(), size);
  // Fewer bytes than the size said (the file shrank meanwhile) is a failed read too.
  return in.gcount() == size ? "" : "read error";
}

std::string WriteFileBytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) return std::strerror(errno);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  return out ? "" : "write error";
}

void CheckWritable(const std::filesystem::path& path, const Mesh& mesh) {
  const std::string problem = mesh.Validate();
  if (!problem.empty()) Fail(path, "refusing to write an inconsistent mesh: {}", problem);
}

bool ParseFloat(std::string_view token, float* value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), *value);
  return error == std::errc() && end == token.data() + token.size();
}

bool ParseDouble(std::string_view token, double* value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), *value);
  return error == std::errc() && end == token.data() + token.size();
}

bool ParseInt(std::string_view token, int64_t* value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), *value);
  return error == std::errc() && end == token.data() + token.size();
}

std::vector<std::string_view> SplitTokens(std::string_view line) {
  std::vector<std::string_view> tokens;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

void AppendFan(const std::vector<int>& corners, Mesh* mesh) {
  for (size_t k = 1; k + 1 < corners.size(); ++k) {
    mesh->faces.emplace_back(corners[0], corners[k], corners[k + 1]);
  }
}

bool LineReader::Next(std::string_view* line) {
  if (offset_ >= text_.size()) return false;
  size_t end = text_.find('\n', offset_);
  const size_t next = end == std::string_view::npos ? text_.size() : end + 1;
  if (end == std::string_view::npos) end = text_.size();
  *line = text_.substr(offset_, end - offset_);
  if (!line->empty() && line->back() == '\r') line->remove_suffix(1);
  offset_ = next;
  ++line_number_;
  return true;
}

}  // namespace mesh_io

Mesh ReadMesh(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  Mesh mesh;
  if (extension == ".ply") {
    mesh = mesh_io::ReadPly(path, mesh_io::ReadWholeFile(path));
  } else if (extension == ".obj") {
    mesh = mesh_io::ReadObj(path, mesh_io::ReadWholeFile(path));
  } else if (extension == ".off") {
    mesh = mesh_io::ReadOff(path, mesh_io::ReadWholeFile(path));
  } else {
    mesh_io::Fail(path, "unknown mesh format '{}' (expected .ply, .obj or .off)", extension);
  }
  // The readers check indices as they go; this catches the rest (e.g. a NaN coordinate).
  const std::string problem = mesh.Validate();
  if (!problem.empty()) mesh_io::Fail(path, "{}", problem);
  return mesh;
}

}  // namespace avc::geometry
