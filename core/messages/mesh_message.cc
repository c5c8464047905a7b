#include "core/messages/mesh_message.h"

#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "core/geometry/mesh_io.h"

namespace avc::messages {
namespace {

// core/geometry reads and writes PLY through files only, so the bytes go through a private
// temporary file (removed on every path out).
class TemporaryPly {
 public:
  TemporaryPly() {
    static std::atomic<uint64_t> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            fmt::format("avc-mesh-{}-{}.ply", getpid(), counter.fetch_add(1));
  }
  ~TemporaryPly() {
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
  }
  TemporaryPly(const TemporaryPly&) = delete;
  TemporaryPly& operator=(const TemporaryPly&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace

avc::mesh_t MeshToMessage(const geometry::Mesh& mesh, const std::string& mesh_id) {
  if (const std::string problem = mesh.Validate(); !problem.empty()) {
    throw std::invalid_argument(fmt::format("mesh '{}': {}", mesh_id, problem));
  }
  const TemporaryPly file;
  geometry::WriteMeshPly(file.path(), mesh, /*binary=*/true);
  std::ifstream in(file.path(), std::ios::binary);
  avc::mesh_t message{};
  message.mesh_id = mesh_id;
  message.frame = "world";
  message.num_vertices = static_cast<int32_t>(mesh.vertices.size());
  message.num_faces = static_cast<int32_t>(mesh.faces.size());
  message.encoding = avc::mesh_t::ENCODING_PLY_BINARY;
  message.data.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  message.data_size = static_cast<int32_t>(message.data.size());
  return message;
}

geometry::Mesh MeshFromMessage(const avc::mesh_t& message) {
  const std::string what = fmt::format("mesh '{}'", message.mesh_id);
  if (message.encoding != avc::mesh_t::ENCODING_PLY_BINARY &&
      message.encoding != avc::mesh_t::ENCODING_PLY_ASCII) {
    throw std::invalid_argument(fmt::format("{}: unknown encoding {}", what, message.encoding));
  }
  if (message.data_size != static_cast<int32_t>(message.data.size())) {
    throw std::invalid_argument(
        fmt::format("{}: data_size {} but {} bytes", what, message.data_size, message.data.size()));
  }
  const TemporaryPly file;
  {
    std::ofstream out(file.path(), std::ios::binary);
    out.write(reinterpret_cast<const char*>(message.data.data()),
              static_cast<std::streamsize>(message.data.size()));
  }
  geometry::Mesh mesh;
  try {
    mesh = geometry::ReadMesh(file.path());
  } catch (const std::runtime_error& error) {
    throw std::invalid_argument(fmt::format("{}: {}", what, error.what()));
  }
  if (mesh.vertices.size() != static_cast<size_t>(message.num_vertices) ||
      mesh.faces.size() != static_cast<size_t>(message.num_faces)) {
    throw std::invalid_argument(fmt::format(
        "{}: announces {} vertices and {} faces, its PLY holds {} and {}", what,
        message.num_vertices, message.num_faces, mesh.vertices.size(), mesh.faces.size()));
  }
  return mesh;
}

}  // namespace avc::messages
