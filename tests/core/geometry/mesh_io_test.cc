// Mesh IO: exact round trips through PLY (binary, ascii), OBJ and OFF, the format features the
// readers accept, and clear errors naming the file for malformed input.

#include "core/geometry/mesh_io.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "tests/support/test_support.h"

namespace avc::geometry {
namespace {

using avc::testing::ReadFile;
using avc::testing::TempDir;
using avc::testing::WriteFile;

// A small mesh with every attribute, including values that are hard to print exactly.
Mesh RichMesh() {
  Mesh mesh;
  const float awkward[] = {0.1f,          -1.0f / 3.0f,    1e-7f,       12345.678f, -0.0f,
                           3.4028235e38f, 1.17549435e-38f, 0.30000001f, 2.0f / 7.0f};
  for (int i = 0; i < 9; ++i) {
    mesh.vertices.emplace_back(awkward[i], awkward[(i + 3) % 9] * 0.5f, static_cast<float>(i));
    mesh.uvs.emplace_back(awkward[(i + 5) % 9], static_cast<float>(i) / 9.0f);
    mesh.colors.emplace_back(static_cast<uint8_t>(i * 31), static_cast<uint8_t>(255 - i),
                             static_cast<uint8_t>(i * 7 + 1));
  }
  for (int i = 0; i < 7; ++i) {
    mesh.faces.emplace_back(i, i + 1, i + 2);
    mesh.face_labels.push_back(i == 0 ? labels::kPot : labels::kLeafBase + i);
    mesh.face_materials.push_back(i * 3 - 1);
  }
  return mesh;
}

bool BitEqual(const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
  return std::memcmp(a.data(), b.data(), sizeof(float) * 3) == 0;
}

void ExpectSameMesh(const Mesh& expected, const Mesh& actual, bool with_labels) {
  ASSERT_EQ(expected.vertices.size(), actual.vertices.size());
  for (size_t i = 0; i < expected.vertices.size(); ++i) {
    EXPECT_TRUE(BitEqual(expected.vertices[i], actual.vertices[i])) << "vertex " << i;
  }
  EXPECT_EQ(expected.faces, actual.faces);
  EXPECT_EQ(expected.colors, actual.colors);
  ASSERT_EQ(expected.uvs.size(), actual.uvs.size());
  for (size_t i = 0; i < expected.uvs.size(); ++i) {
    EXPECT_EQ(std::memcmp(expected.uvs[i].data(), actual.uvs[i].data(), 8), 0) << "uv " << i;
  }
  if (with_labels) {
    EXPECT_EQ(expected.face_labels, actual.face_labels);
    EXPECT_EQ(expected.face_materials, actual.face_materials);
  }
}

// Runs f, expecting a std::runtime_error whose message contains every one of parts.
template <class F>
void ExpectError(F f, std::initializer_list<std::string> parts) {
  try {
    f();
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& error) {
    for (const std::string& part : parts) {
      EXPECT_NE(std::string(error.what()).find(part), std::string::npos)
          << "'" << error.what() << "' lacks '" << part << "'";
    }
  }
}

TEST(MeshIo, BinaryPlyRoundTripIsExactAndDeterministic) {
  TempDir dir;
  const Mesh mesh = RichMesh();
  WriteMeshPly(dir / "a.ply", mesh, true);
  WriteMeshPly(dir / "b.ply", mesh, true);
  EXPECT_EQ(ReadFile(dir / "a.ply"), ReadFile(dir / "b.ply"));
  ExpectSameMesh(mesh, ReadMesh(dir / "a.ply"), true);
}

TEST(MeshIo, AsciiPlyRoundTripIsExact) {
  TempDir dir;
  const Mesh mesh = RichMesh();
  WriteMeshPly(dir / "a.ply", mesh, false);
  EXPECT_NE(ReadFile(dir / "a.ply").find("format ascii 1.0"), std::string::npos);
  ExpectSameMesh(mesh, ReadMesh(dir / "a.ply"), true);
}

TEST(MeshIo, PlyWithoutOptionalAttributesStaysWithout) {
  TempDir dir;
  Mesh mesh = RichMesh();
  mesh.uvs.clear();
  mesh.colors.clear();
  mesh.face_labels.clear();
  mesh.face_materials.clear();
  WriteMeshPly(dir / "plain.ply", mesh);
  const Mesh back = ReadMesh(dir / "plain.ply");
  ExpectSameMesh(mesh, back, true);
  EXPECT_TRUE(back.uvs.empty() && back.colors.empty() && back.face_labels.empty());
}

TEST(MeshIo, ObjRoundTripIsExact) {
  TempDir dir;
  const Mesh mesh = RichMesh();
  WriteMeshObj(dir / "a.obj", mesh);
  ExpectSameMesh(mesh, ReadMesh(dir / "a.obj"), false);
}

TEST(MeshIo, OffRoundTripIsExact) {
  TempDir dir;
  Mesh mesh = RichMesh();
  mesh.uvs.clear();
  WriteMeshOff(dir / "a.OFF", mesh);  // the extension is matched in any case
  ExpectSameMesh(mesh, ReadMesh(dir / "a.OFF"), false);
}

TEST(MeshIo, ObjFormsNegativeIndicesPolygonsAndSplitTexcoords) {
  TempDir dir;
  WriteFile(dir / "q.obj",
            "# quad and triangle\n"
            "o thing\n"
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
            "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n"
            "vn 0 0 1\n"
            "f 1/1/1 2/2/1 3/3/1 4/4/1\n"
            "f -4//1 -2//1 -1//1\n"
            "f 1/5 2/2 3/3\n");
  const Mesh mesh = ReadMesh(dir / "q.obj");
  // The quad is fanned into two triangles; vertex 1 used with a second vt gets a copy.
  ASSERT_EQ(mesh.faces.size(), 4u);
  EXPECT_EQ(mesh.faces[0], Eigen::Vector3i(0, 1, 2));
  EXPECT_EQ(mesh.faces[1], Eigen::Vector3i(0, 2, 3));
  EXPECT_EQ(mesh.faces[2], Eigen::Vector3i(0, 2, 3));
  ASSERT_EQ(mesh.vertices.size(), 5u);
  EXPECT_EQ(mesh.faces[3], Eigen::Vector3i(4, 1, 2));
  EXPECT_EQ(mesh.vertices[4], mesh.vertices[0]);
  EXPECT_EQ(mesh.uvs[4], Eigen::Vector2f(0.5f, 0.5f));
  EXPECT_EQ(mesh.uvs[3], Eigen::Vector2f(0.0f, 1.0f));
}

TEST(MeshIo, PlyVariantsAreRead) {
  TempDir dir;
  // Ascii: extra element and properties, float colours, s/t texcoords, a quad, vertex_index.
  WriteFile(dir / "v.ply",
            "ply\nformat ascii 1.0\ncomment test\n"
            "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
            "property float confidence\nproperty float red\nproperty float green\n"
            "property float blue\nproperty float s\nproperty float t\n"
            "element material 1\nproperty uchar id\n"
            "element face 1\nproperty list uchar uint vertex_index\nproperty short label\n"
            "end_header\n"
            "0 0 0 0.5 1 0 0 0 0\n1 0 0 0.5 0 1 0 1 0\n1 1 0 0.5 0 0 1 1 1\n"
            "0 1 0 0.5 0.5 0.5 0.5 0 1\n"
            "7\n"
            "4 0 1 2 3 104\n");
  const Mesh mesh = ReadMesh(dir / "v.ply");
  ASSERT_EQ(mesh.faces.size(), 2u);
  EXPECT_EQ(mesh.faces[1], Eigen::Vector3i(0, 2, 3));
  EXPECT_EQ(mesh.face_labels, (std::vector<int32_t>{104, 104}));
  EXPECT_EQ(mesh.colors[0], (Eigen::Matrix<uint8_t, 3, 1>(255, 0, 0)));
  EXPECT_EQ(mesh.colors[3], (Eigen::Matrix<uint8_t, 3, 1>(128, 128, 128)));
  EXPECT_EQ(mesh.uvs[2], Eigen::Vector2f(1, 1));

  // Binary big endian: three vertices of doubles and one triangle.
  std::string bytes =
      "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty double x\n"
      "property double y\nproperty double z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  auto put_be = [&bytes](uint64_t bits, int size) {
    for (int k = size - 1; k >= 0; --k)
      bytes.push_back(static_cast<char>((bits >> (8 * k)) & 0xff));
  };
  const double coordinates[9] = {0, 0, 0, 1.5, 0, 0, 0, -2.25, 0};
  for (double c : coordinates) {
    uint64_t bits;
    std::memcpy(&bits, &c, 8);
    put_be(bits, 8);
  }
  put_be(3, 1);
  for (int i : {0, 1, 2}) put_be(static_cast<uint64_t>(i), 4);
  WriteFile(dir / "be.ply", bytes);
  const Mesh big = ReadMesh(dir / "be.ply");
  ASSERT_EQ(big.vertices.size(), 3u);
  EXPECT_EQ(big.vertices[1], Eigen::Vector3f(1.5f, 0, 0));
  EXPECT_EQ(big.vertices[2], Eigen::Vector3f(0, -2.25f, 0));
  EXPECT_EQ(big.faces[0], Eigen::Vector3i(0, 1, 2));
}

TEST(MeshIo, OffVariantsAreRead) {
  TempDir dir;
  WriteFile(dir / "c.off",
            "COFF 5 2 0 # counts on the header line\n"
            "# a comment line\n"
            "0 0 0 1.0 0.0 0.0 1.0\n1 0 0 255 255 255 255\n1 1 0 0 0 0 255\n"
            "0 1 0 10 20 30 255\n\n0.5 0.5 1 1 2 3 255\n"
            "4 0 1 2 3\n3 0 1 4\n");
  const Mesh mesh = ReadMesh(dir / "c.off");
  ASSERT_EQ(mesh.vertices.size(), 5u);
  ASSERT_EQ(mesh.faces.size(), 3u);
  EXPECT_EQ(mesh.faces[2], Eigen::Vector3i(0, 1, 4));
  EXPECT_EQ(mesh.colors[0], (Eigen::Matrix<uint8_t, 3, 1>(255, 0, 0)));
  EXPECT_EQ(mesh.colors[3], (Eigen::Matrix<uint8_t, 3, 1>(10, 20, 30)));
}

TEST(MeshIo, GeneratedLargeMeshRoundTripsInEveryFormat) {
  // A 200 x 200 grid with irrational coordinates: many values to print and parse exactly.
  Mesh mesh;
  const int n = 200;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const float x = static_cast<float>(i) * 0.0137f - 1.3f;
      const float y = static_cast<float>(j) * 0.0291f + 0.7f;
      mesh.vertices.emplace_back(x, y, std::sin(x * 3.1f) * std::cos(y * 1.7f));
      mesh.uvs.emplace_back(x / 3.0f, y / 7.0f);
    }
  }
  for (int i = 0; i + 1 < n; ++i) {
    for (int j = 0; j + 1 < n; ++j) {
      const int a = i * n + j;
      mesh.faces.emplace_back(a, a + n, a + n + 1);
      mesh.faces.emplace_back(a, a + n + 1, a + 1);
    }
  }
  TempDir dir;
  WriteMeshPly(dir / "g.ply", mesh, true);
  ExpectSameMesh(mesh, ReadMesh(dir / "g.ply"), true);
  WriteMeshPly(dir / "g_ascii.ply", mesh, false);
  ExpectSameMesh(mesh, ReadMesh(dir / "g_ascii.ply"), true);
  WriteMeshObj(dir / "g.obj", mesh);
  ExpectSameMesh(mesh, ReadMesh(dir / "g.obj"), true);
  mesh.uvs.clear();
  WriteMeshOff(dir / "g.off", mesh);
  ExpectSameMesh(mesh, ReadMesh(dir / "g.off"), true);
}

TEST(MeshIo, TruncatedBinaryPlyNamesFileAndElement) {
  TempDir dir;
  WriteMeshPly(dir / "whole.ply", RichMesh(), true);
  const std::string bytes = ReadFile(dir / "whole.ply");
  WriteFile(dir / "cut.ply", bytes.substr(0, bytes.size() - 10));
  ExpectError([&] { ReadMesh(dir / "cut.ply"); }, {"cut.ply", "face 6 of 7", "end of file"});
  WriteFile(dir / "cut_early.ply", bytes.substr(0, bytes.find("end_header") + 11 + 30));
  ExpectError([&] { ReadMesh(dir / "cut_early.ply"); }, {"cut_early.ply", "vertex 1 of 9"});
}

TEST(MeshIo, BadIndicesNameFileFaceAndVertex) {
  TempDir dir;
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n";
  WriteFile(dir / "bad.ply", header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 900\n");
  ExpectError([&] { ReadMesh(dir / "bad.ply"); }, {"bad.ply: face 1 refers to vertex 900 of 3"});
  WriteFile(dir / "neg.ply", header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 -1 2\n");
  ExpectError([&] { ReadMesh(dir / "neg.ply"); }, {"neg.ply: face 1 refers to vertex -1 of 3"});
  WriteFile(dir / "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n");
  ExpectError([&] { ReadMesh(dir / "bad.obj"); },
              {"bad.obj: line 5: face 1 refers to vertex 4 of 3"});
  WriteFile(dir / "bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
  ExpectError([&] { ReadMesh(dir / "bad.off"); },
              {"bad.off: line 6: face 0 refers to vertex 3 of 3"});
  WriteFile(dir / "float_index.ply",
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
            "property float z\nelement face 1\nproperty list uchar float vertex_indices\n"
            "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1.5 2\n");
  ExpectError([&] { ReadMesh(dir / "float_index.ply"); },
              {"float_index.ply: face 0 of 1: vertex_indices is 1.5, not a whole number"});
  WriteFile(dir / "nan.ply", header + "0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n");
  ExpectError([&] { ReadMesh(dir / "nan.ply"); }, {"nan.ply", "vertex 1 is not finite"});
}

TEST(MeshIo, BadHeadersAndEmptyFilesNameTheFile) {
  TempDir dir;
  WriteFile(dir / "empty.ply", "");
  ExpectError([&] { ReadMesh(dir / "empty.ply"); }, {"empty.ply", "empty"});
  WriteFile(dir / "magic.ply", "plx\nformat ascii 1.0\nend_header\n");
  ExpectError([&] { ReadMesh(dir / "magic.ply"); }, {"magic.ply", "line 1", "not a PLY"});
  WriteFile(dir / "type.ply",
            "ply\nformat ascii 1.0\nelement vertex 1\nproperty quaternion x\nend_header\n");
  ExpectError([&] { ReadMesh(dir / "type.ply"); }, {"type.ply", "line 4", "quaternion"});
  WriteFile(dir / "noend.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n");
  ExpectError([&] { ReadMesh(dir / "noend.ply"); }, {"noend.ply", "end_header"});
  WriteFile(dir / "text.ply",
            "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
            "property float z\nend_header\n0 zero 0\n");
  ExpectError([&] { ReadMesh(dir / "text.ply"); }, {"text.ply", "vertex 0 of 1", "line 8"});
  WriteFile(dir / "empty.off", "# nothing\n");
  ExpectError([&] { ReadMesh(dir / "empty.off"); }, {"empty.off"});
  WriteFile(dir / "short.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n");
  ExpectError([&] { ReadMesh(dir / "short.off"); }, {"short.off", "4 vertices and 2 faces"});
  WriteFile(dir / "empty.obj", "# no vertices\n");
  ExpectError([&] { ReadMesh(dir / "empty.obj"); }, {"empty.obj", "no vertices"});
  WriteFile(dir / "mesh.stl", "solid\n");
  ExpectError([&] { ReadMesh(dir / "mesh.stl"); }, {"mesh.stl", "unknown mesh format"});
  ExpectError([&] { ReadMesh(dir / "missing.ply"); }, {"missing.ply", "no such file"});
}

TEST(MeshIo, WritingAnInconsistentMeshIsRefused) {
  TempDir dir;
  Mesh mesh = RichMesh();
  mesh.faces[2] = Eigen::Vector3i(0, 1, 99);
  ExpectError([&] { WriteMeshPly(dir / "x.ply", mesh); }, {"x.ply", "face 2 refers to vertex 99"});
  EXPECT_FALSE(std::filesystem::exists(dir / "x.ply"));
}

}  // namespace
}  // namespace avc::geometry
