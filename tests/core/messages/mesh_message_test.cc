// Meshes on the bus: mesh_t carries the mesh as binary PLY; the round trip is exact, the same mesh
// gives the same bytes, and a message whose counts or data do not match is refused naming it.

#include "core/messages/mesh_message.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace avc::messages {
namespace {

// Two triangles of a leaf and one of a stem, with per-vertex colours.
geometry::Mesh LabelledMesh() {
  geometry::Mesh mesh;
  mesh.vertices = {
      {0, 0, 0}, {0.01f, 0, 0}, {0, 0.01f, 0.002f}, {0.01f, 0.01f, 0.004f}, {0, 0, 0.05f}};
  mesh.faces = {{0, 1, 2}, {1, 3, 2}, {0, 4, 1}};
  mesh.face_labels = {geometry::labels::kLeafBase, geometry::labels::kLeafBase,
                      geometry::labels::kStem};
  for (int v = 0; v < 5; ++v) {
    mesh.colors.push_back({static_cast<uint8_t>(40 * v), 200, static_cast<uint8_t>(255 - 30 * v)});
  }
  return mesh;
}

TEST(MeshMessage, RoundTripsExactlyWithTheSameBytes) {
  const geometry::Mesh mesh = LabelledMesh();
  const avc::mesh_t a = MeshToMessage(mesh, "m");
  const avc::mesh_t b = MeshToMessage(mesh, "m");
  EXPECT_EQ(a.data, b.data);
  EXPECT_EQ(a.num_faces, static_cast<int32_t>(mesh.faces.size()));
  const geometry::Mesh back = MeshFromMessage(a);
  EXPECT_EQ(back.vertices, mesh.vertices);
  EXPECT_EQ(back.faces, mesh.faces);
  EXPECT_EQ(back.face_labels, mesh.face_labels);
  EXPECT_EQ(back.colors, mesh.colors);
  EXPECT_EQ(MeshFromMessage(MeshToMessage(geometry::Mesh{}, "empty")).vertices.size(), 0u);
}

TEST(MeshMessage, RefusesCountsOrDataThatDoNotMatch) {
  const avc::mesh_t good = MeshToMessage(LabelledMesh(), "m");
  avc::mesh_t lying = good;
  lying.num_faces += 1;
  EXPECT_THROW(MeshFromMessage(lying), std::invalid_argument);
  avc::mesh_t cut = good;
  cut.data.resize(cut.data.size() / 2);
  cut.data_size = static_cast<int32_t>(cut.data.size());
  try {
    MeshFromMessage(cut);
    ADD_FAILURE() << "a truncated PLY was accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("mesh 'm'"), std::string::npos) << error.what();
  }
  geometry::Mesh broken = LabelledMesh();
  broken.faces.push_back({0, 1, 9});
  EXPECT_THROW(MeshToMessage(broken, "broken"), std::invalid_argument);
}

}  // namespace
}  // namespace avc::messages
