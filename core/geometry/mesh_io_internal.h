#pragma once

// Pieces shared by the PLY (ply_table, ply_writer), OBJ and OFF readers and writers and the point
// cloud IO (not part of the public API).

#include <fmt/format.h>

#include <charconv>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/geometry/mesh.h"

namespace avc::geometry::mesh_io {

// Throws std::runtime_error("<file name>: <message>").
template <class... Args>
[[noreturn]] void Fail(const std::filesystem::path& path, fmt::format_string<Args...> format,
                       Args&&... args) {
  throw std::runtime_error(fmt::format("{}: {}", path.filename().string(),
                                       fmt::format(format, std::forward<Args>(args)...)));
}

// The whole file as bytes; throws when it cannot be read or is empty.
std::string ReadWholeFile(const std::filesystem::path& path);
// Writes bytes (replacing the file); throws naming the file on failure.
void WriteWholeFile(const std::filesystem::path& path, const std::string& bytes);
// The same without the wording, for callers that word errors their own way: the whole file into
// *bytes in one read (files can be large) / bytes into the file. Return why they failed (e.g.
// "Is a directory"), empty on success.
std::string ReadFileBytes(const std::filesystem::path& path, std::string* bytes);
std::string WriteFileBytes(const std::filesystem::path& path, const std::string& bytes);
// Throws naming the file when the mesh is not consistent (Mesh::Validate).
void CheckWritable(const std::filesystem::path& path, const Mesh& mesh);

// Text parsing: exact for floats (parsed as float, not via double, so shortest decimal forms
// round-trip bit-exact).
bool ParseFloat(std::string_view token, float* value);
bool ParseDouble(std::string_view token, double* value);
bool ParseInt(std::string_view token, int64_t* value);

// Splits a line into whitespace-separated tokens (views into line).
std::vector<std::string_view> SplitTokens(std::string_view line);

// Appends the polygon corners as a fan of triangles; the caller has checked the indices.
void AppendFan(const std::vector<int>& corners, Mesh* mesh);

// Splits text into lines (without the line break; handles \n and \r\n).
class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {}
  // Next line into *line; false at the end. line_number() is then its 1-based number.
  bool Next(std::string_view* line);
  int line_number() const { return line_number_; }
  // Bytes consumed so far (start of the next line).
  size_t offset() const { return offset_; }

 private:
  std::string_view text_;
  size_t offset_ = 0;
  int line_number_ = 0;
};

// Mesh IO for one format (mesh_io.cc dispatches on the extension).
Mesh ReadPly(const std::filesystem::path& path, const std::string& bytes);
Mesh ReadObj(const std::filesystem::path& path, const std::string& bytes);
Mesh ReadOff(const std::filesystem::path& path, const std::string& bytes);

}  // namespace avc::geometry::mesh_io
