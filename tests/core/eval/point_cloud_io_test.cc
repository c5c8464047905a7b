// Point cloud files: PLY (ascii, binary, big endian, mesh files), XYZ, and clear errors.

#include "core/geometry/point_cloud_io.h"

#include <gtest/gtest.h>

#include <cstring>

#include "tests/support/test_support.h"

namespace avc::geometry {
namespace {

using avc::testing::ReadFile;
using avc::testing::TempDir;
using avc::testing::WriteFile;

PointCloud Sample() {
  PointCloud cloud;
  cloud.positions = {{0.1f, -2.5f, 3e-7f}, {1.0f / 3.0f, 123.456f, -0.0f}, {7, 8, 9}};
  cloud.normals = {{0, 0, 1}, {0.6f, 0.8f, 0}, {1, 0, 0}};
  cloud.colors = {{255, 0, 1}, {2, 128, 254}, {10, 20, 30}};
  return cloud;
}

void ExpectSame(const PointCloud& a, const PointCloud& b) {
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.normals, b.normals);
  EXPECT_EQ(a.colors, b.colors);
}

std::string ErrorOf(const std::filesystem::path& path) {
  try {
    ReadPointCloud(path);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "accepted";
}

TEST(PointCloudIo, PlyRoundTripsExactlyInBinaryAndAscii) {
  TempDir dir;
  for (const bool binary : {true, false}) {
    const std::filesystem::path path = dir / (binary ? "b.ply" : "a.ply");
    WritePointCloudPly(path, Sample(), binary);
    ExpectSame(ReadPointCloud(path), Sample());
    EXPECT_FALSE(PlyHasFaces(path));
    const std::string first = ReadFile(path);
    WritePointCloudPly(path, Sample(), binary);
    EXPECT_EQ(ReadFile(path), first);
  }
}

TEST(PointCloudIo, ReadsBigEndianAndSkipsOtherElements) {
  TempDir dir;
  // A face element before the vertices (with a list property), double coordinates, big endian.
  std::string ply =
      "ply\nformat binary_big_endian 1.0\ncomment made by hand\nelement face 1\n"
      "property list uchar int vertex_indices\nelement vertex 2\nproperty double x\n"
      "property double y\nproperty double z\nproperty float confidence\nend_header\n";
  auto append_big = [&ply](auto value) {
    char bytes[sizeof(value)];
    std::memcpy(bytes, &value, sizeof(value));
    for (size_t k = sizeof(value); k-- > 0;) ply += bytes[k];
  };
  append_big(uint8_t{3});
  for (int32_t index : {0, 1, 1}) append_big(index);
  for (double v : {1.5, -2.0, 0.25}) append_big(v);
  append_big(0.5f);
  for (double v : {4.0, 5.0, 6.0}) append_big(v);
  append_big(0.5f);
  WriteFile(dir / "big.ply", ply);
  const PointCloud cloud = ReadPointCloud(dir / "big.ply");
  ASSERT_EQ(cloud.size(), 2u);
  EXPECT_EQ(cloud.positions[0], Eigen::Vector3f(1.5f, -2.0f, 0.25f));
  EXPECT_EQ(cloud.positions[1], Eigen::Vector3f(4, 5, 6));
  EXPECT_TRUE(cloud.normals.empty());
  EXPECT_TRUE(PlyHasFaces(dir / "big.ply"));
}

TEST(PointCloudIo, MeshPlyReadsAsItsVerticesWithoutReadingTheFaces) {
  TempDir dir;
  // Float colours (0..1), and a face section cut short: the cloud never reads it.
  WriteFile(dir / "mesh.ply",
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
            "property float z\nproperty float red\nproperty float green\nproperty float blue\n"
            "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
            "0 0 0 1 0.5 0\n1 0 0 0 0.2 2\n0 1 0.5 -1 0.0039 1\n3 0 1 2\n3 0\n");
  const PointCloud cloud = ReadPointCloud(dir / "mesh.ply");
  ASSERT_EQ(cloud.size(), 3u);
  EXPECT_EQ(cloud.positions[2], Eigen::Vector3f(0, 1, 0.5f));
  EXPECT_EQ(cloud.colors[0], (Eigen::Matrix<uint8_t, 3, 1>(255, 128, 0)));
  EXPECT_EQ(cloud.colors[1], (Eigen::Matrix<uint8_t, 3, 1>(0, 51, 255)));
  EXPECT_EQ(cloud.colors[2], (Eigen::Matrix<uint8_t, 3, 1>(0, 1, 255)));
  EXPECT_TRUE(PlyHasFaces(dir / "mesh.ply"));
}

TEST(PointCloudIo, XyzWithAndWithoutNormals) {
  TempDir dir;
  WriteFile(dir / "p.xyz", "# a comment\n1 2 3\n\n4.5 -5 6e-3\n");
  const PointCloud plain = ReadPointCloud(dir / "p.xyz");
  ASSERT_EQ(plain.size(), 2u);
  EXPECT_EQ(plain.positions[1], Eigen::Vector3f(4.5f, -5.0f, 6e-3f));
  EXPECT_TRUE(plain.normals.empty());
  WriteFile(dir / "n.XYZ", "1 2 3 0 0 1\r\n4 5 6 1 0 0\r\n");
  const PointCloud with_normals = ReadPointCloud(dir / "n.XYZ");
  ASSERT_EQ(with_normals.normals.size(), 2u);
  EXPECT_EQ(with_normals.normals[1], Eigen::Vector3f(1, 0, 0));
}

TEST(PointCloudIo, BadFilesNameTheFileAndPlace) {
  TempDir dir;
  EXPECT_NE(ErrorOf(dir / "missing.ply").find("missing.ply: no such file"), std::string::npos);
  std::filesystem::create_directory(dir / "folder.ply");
  EXPECT_NE(ErrorOf(dir / "folder.ply").find("folder.ply: cannot read"), std::string::npos)
      << ErrorOf(dir / "folder.ply");
  const std::string xyz_header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n";
  struct BadFile {
    const char* name;
    std::string contents;
    const char* error;  // a part of the message
  };
  const BadFile bad_files[] = {
      // The PLY reader is shared with ReadMesh, so the wording is the same: element, index of
      // count, and the line in ascii files.
      {"short.ply", xyz_header + "1 2 3\n4 5\n",
       "short.ply: vertex 1 of 3: unexpected end of file"},
      {"word.ply", xyz_header + "1 two 3\n", "vertex 0 of 3: line 8: 'two' is not a number"},
      {"noz.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n1\n",
       "no x, y and z"},
      {"text.ply", "hello\n", "not a PLY file"},
      {"nan.ply", xyz_header + "1 nan 3\n0 0 0\n0 0 0\n", "vertex 0 is not finite"},
      {"ragged.xyz", "1 2 3\n1 2 3 4\n", "ragged.xyz: line 2: 4 numbers"},
      {"cloud.stl", "solid\n", "unknown point cloud format"},
  };
  for (const BadFile& bad : bad_files) {
    WriteFile(dir / bad.name, bad.contents);
    const std::string error = ErrorOf(dir / bad.name);
    EXPECT_NE(error.find(bad.error), std::string::npos) << "'" << error << "' lacks " << bad.error;
  }
}

}  // namespace
}  // namespace avc::geometry
