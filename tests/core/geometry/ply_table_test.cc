// The shared PLY table reader and writer (core/geometry/ply_table.h, ply_writer.h): every type in
// both byte orders, list columns, which elements are kept and read, corrupt counts, and the exact
// bytes the writer produces.

#include "core/geometry/ply_table.h"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "core/geometry/ply_writer.h"

namespace avc::geometry::ply {
namespace {

// Appends value's bytes in the given byte order.
template <class T>
void Append(std::string* bytes, T value, bool big_endian) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  const bool native_big = std::endian::native == std::endian::big;
  for (size_t k = 0; k < sizeof(T); ++k) {
    bytes->push_back(raw[big_endian != native_big ? sizeof(T) - 1 - k : k]);
  }
}

// Every value of a column.
std::vector<double> Values(const Column& column) {
  std::vector<double> values;
  for (size_t i = 0; i < column.size(); ++i) values.push_back(column[i]);
  return values;
}

// The items of one instance of a list column.
std::vector<double> Values(const Column& column, size_t instance) {
  std::vector<double> values;
  for (size_t k = column.ListBegin(instance); k < column.ListEnd(instance); ++k) {
    values.push_back(column[k]);
  }
  return values;
}

Table Read(const std::string& bytes, std::initializer_list<std::string_view> keep,
           bool read_whole_body = true) {
  Table table = ParseHeader("t.ply", bytes);
  ReadBody("t.ply", bytes, keep, read_whole_body, &table);
  return table;
}

std::string ErrorOf(const std::string& bytes, std::initializer_list<std::string_view> keep) {
  try {
    Read(bytes, keep);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "accepted";
}

TEST(PlyTable, EveryTypeInBothByteOrdersIsReadExactly) {
  for (const bool big : {false, true}) {
    std::string bytes = std::string("ply\nformat ") +
                        (big ? "binary_big_endian" : "binary_little_endian") +
                        " 1.0\nelement v 2\nproperty char a\nproperty uchar b\nproperty short c\n"
                        "property ushort d\nproperty int e\nproperty uint f\nproperty float g\n"
                        "property double h\nproperty list uint16 int8 l\nend_header\n";
    for (int i = 0; i < 2; ++i) {
      Append(&bytes, static_cast<int8_t>(i == 0 ? -128 : 127), big);
      Append(&bytes, static_cast<uint8_t>(i == 0 ? 0 : 255), big);
      Append(&bytes, static_cast<int16_t>(i == 0 ? -32768 : 32767), big);
      Append(&bytes, static_cast<uint16_t>(i == 0 ? 1 : 65535), big);
      Append(&bytes, std::numeric_limits<int32_t>::min() + i, big);
      Append(&bytes, std::numeric_limits<uint32_t>::max() - static_cast<uint32_t>(i), big);
      Append(&bytes, i == 0 ? 0.1f : -3.4028235e38f, big);
      Append(&bytes, i == 0 ? 1.0 / 3.0 : -1e-300, big);
      Append(&bytes, static_cast<uint16_t>(i + 1), big);
      for (int k = 0; k <= i; ++k) Append(&bytes, static_cast<int8_t>(-k - 1), big);
    }
    const Table table = Read(bytes, {"v"});
    ASSERT_EQ(table.elements.size(), 1u);
    const Element& v = table.elements[0];
    ASSERT_EQ(v.columns.size(), 9u);
    EXPECT_EQ(Values(v.columns[0]), (std::vector<double>{-128, 127}));
    EXPECT_EQ(Values(v.columns[1]), (std::vector<double>{0, 255}));
    EXPECT_EQ(Values(v.columns[2]), (std::vector<double>{-32768, 32767}));
    EXPECT_EQ(Values(v.columns[3]), (std::vector<double>{1, 65535}));
    EXPECT_EQ(Values(v.columns[4]), (std::vector<double>{-2147483648.0, -2147483647.0}));
    EXPECT_EQ(Values(v.columns[5]), (std::vector<double>{4294967295.0, 4294967294.0}));
    EXPECT_EQ(Values(v.columns[6]), (std::vector<double>{0.1f, -3.4028235e38f}));
    EXPECT_EQ(Values(v.columns[7]), (std::vector<double>{1.0 / 3.0, -1e-300}));
    EXPECT_EQ(Values(v.columns[8], 0), (std::vector<double>{-1}));
    EXPECT_EQ(Values(v.columns[8], 1), (std::vector<double>{-1, -2}));
    EXPECT_EQ(v.columns[6].type(), Type::kFloat32);
    EXPECT_EQ(v.columns[6].width(), 4u);
    EXPECT_EQ(Values(v.columns[8]), (std::vector<double>{-1, -1, -2}));
    EXPECT_EQ(v.properties[8].count_type, Type::kUint16);
    EXPECT_EQ(v.properties[8].type, Type::kInt8);
  }
}

TEST(PlyTable, OnlyKeptElementsGetColumnsAndReadingCanStopAfterThem) {
  const std::string header =
      "ply\nformat ascii 1.0\ncomment c\nelement skip 1\nproperty list uchar float junk\n"
      "element vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nproperty int label\n"
      "end_header\n";
  const std::string body = "2 0.5 7\n0.1 0.2 0.3\n+4 5e-3 -6\n";
  const Table table = Read(header + body + "4 0 1 1 0 9\n", {"vertex", "face"});
  EXPECT_TRUE(table.elements[0].columns.empty());
  const Element* vertex = table.Find("vertex");
  ASSERT_NE(vertex, nullptr);
  EXPECT_EQ(vertex->FindScalar({"nothing", "y"}), 1);
  EXPECT_EQ(vertex->FindList({"y"}), -1);
  EXPECT_EQ(Values(vertex->columns[0]), (std::vector<double>{0.1f, 4}));
  EXPECT_EQ(Values(vertex->columns[1]), (std::vector<double>{0.2f, 5e-3f}));
  const Element* face = table.Find("face");
  ASSERT_NE(face, nullptr);
  EXPECT_EQ(Values(face->columns[0], 0), (std::vector<double>{0, 1, 1, 0}));
  EXPECT_EQ(Values(face->columns[1]), (std::vector<double>{9}));
  EXPECT_EQ(Vector3fColumns(*vertex, FindTriple(*vertex, {"x"}, {"y"}, {"z"}))[1],
            Eigen::Vector3f(4, 5e-3f, -6));
  EXPECT_EQ(FindTriple(*vertex, {"x"}, {"nope"}, {"z"}), (std::array<int, 3>{-1, -1, -1}));

  // Garbage after the vertices: an error when the whole body is read, unseen when it is not.
  const std::string broken = header + body + "4 0 1\n";
  EXPECT_NE(ErrorOf(broken, {"vertex"}).find("t.ply: face 0 of 1: unexpected end of file"),
            std::string::npos)
      << ErrorOf(broken, {"vertex"});
  const Table vertices_only = Read(broken, {"vertex"}, /*read_whole_body=*/false);
  EXPECT_EQ(Values(vertices_only.Find("vertex")->columns[2]), (std::vector<double>{0.3f, -6}));
  EXPECT_TRUE(vertices_only.Find("face")->columns.empty());
}

TEST(PlyTable, ColorsScaleFloatsAndClamp) {
  const Table table = Read(
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty double r\nproperty float green\n"
      "property int diffuse_blue\nend_header\n1 0.5 300\n-0.5 0.2 -4\nnan 0.0039 17\n",
      {"vertex"});
  const auto colors = Colors(table.elements[0]);
  ASSERT_EQ(colors.size(), 3u);
  EXPECT_EQ(colors[0], (Eigen::Matrix<uint8_t, 3, 1>(255, 128, 255)));
  EXPECT_EQ(colors[1], (Eigen::Matrix<uint8_t, 3, 1>(0, 51, 0)));
  EXPECT_EQ(colors[2], (Eigen::Matrix<uint8_t, 3, 1>(0, 1, 17)));
}

TEST(PlyTable, ErrorsNameFileLineElementAndIndex) {
  const std::string ascii = "ply\nformat ascii 1.0\nelement vertex 2\nproperty uchar a\n";
  EXPECT_EQ(ErrorOf(ascii + "end_header\n1\n2.5\n", {"vertex"}),
            "t.ply: vertex 1 of 2: line 7: '2.5' is not a number of the declared type");
  // Columns keep the declared type, so an ascii value it cannot hold is refused, not wrapped.
  EXPECT_EQ(ErrorOf(ascii + "end_header\n1\n300\n", {"vertex"}),
            "t.ply: vertex 1 of 2: line 7: '300' is not a number of the declared type");
  EXPECT_EQ(ErrorOf(ascii + "property list int int l\nend_header\n1 2000000\n", {"vertex"}),
            "t.ply: vertex 0 of 2: bad list length 2000000");
  EXPECT_EQ(ErrorOf(ascii + "property float\nend_header\n", {}),
            "t.ply: line 5: expected 'property <type> <name>' or 'property list ...'");
  EXPECT_EQ(ErrorOf("ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\n"
                    "end_header\nabc",
                    {"vertex"}),
            "t.ply: vertex 0 of 1: unexpected end of file (the data ends at byte 84)");
  EXPECT_EQ(ErrorOf("ply\r\nformat ascii 2.0 extra\r\nend_header\r\n", {}),
            "t.ply: line 2: expected 'format <type> 1.0'");
  // A corrupt count must fail on the missing data, not on allocating for a trillion vertices.
  EXPECT_EQ(ErrorOf("ply\nformat binary_little_endian 1.0\nelement vertex 1000000000000\n"
                    "property float x\nproperty float y\nproperty float z\nend_header\n"
                    "0123456789ab",
                    {"vertex"}),
            "t.ply: vertex 1 of 1000000000000: unexpected end of file (the data ends at byte "
            "139)");
}

TEST(PlyWriter, WritesTheDeclaredHeaderAndRecordsInBothFormats) {
  for (const bool binary : {false, true}) {
    Writer writer(binary);
    writer.AddComment("hello");
    writer.AddElement("vertex", 2);
    writer.AddProperty(Type::kFloat32, "x");
    writer.AddProperty(Type::kUint8, "red");
    writer.AddElement("face", 1);
    writer.AddListProperty(Type::kUint8, Type::kInt32, "vertex_indices");
    writer.EndHeader();
    for (const float x : {0.1f, -1.0f / 3.0f}) {
      writer.Put(x);
      writer.Put(uint8_t{200});
      writer.EndRecord();
    }
    writer.Put(uint8_t{2});
    writer.Put(int32_t{-7});
    writer.Put(int32_t{1 << 30});
    writer.EndRecord();
    const std::string bytes = writer.TakeBytes();
    const std::string header = std::string("ply\nformat ") +
                               (binary ? "binary_little_endian" : "ascii") +
                               " 1.0\ncomment lengths in metres\ncomment hello\nelement vertex 2\n"
                               "property float x\n"
                               "property uchar red\nelement face 1\n"
                               "property list uchar int vertex_indices\nend_header\n";
    ASSERT_EQ(bytes.substr(0, header.size()), header);
    if (binary) {
      std::string body;
      Append(&body, 0.1f, false);
      body.push_back(static_cast<char>(200));
      Append(&body, -1.0f / 3.0f, false);
      body.push_back(static_cast<char>(200));
      body.push_back(2);
      Append(&body, int32_t{-7}, false);
      Append(&body, int32_t{1 << 30}, false);
      EXPECT_EQ(bytes.substr(header.size()), body);
    } else {
      EXPECT_EQ(bytes.substr(header.size()), "0.1 200\n-0.33333334 200\n2 -7 1073741824\n");
    }
    const Table table = Read(bytes, {"vertex", "face"});
    EXPECT_EQ(Values(table.elements[0].columns[0]), (std::vector<double>{0.1f, -1.0f / 3.0f}));
    EXPECT_EQ(Values(table.elements[1].columns[0]), (std::vector<double>{-7, 1 << 30}));
  }
}

}  // namespace
}  // namespace avc::geometry::ply
