#pragma once

// PLY files read as tables: the header (format, elements, their scalar and list properties) and,
// per element, one column of values per property. The one PLY parser behind ReadMesh
// (ply_io.cc) and ReadPointCloud (point_cloud_io.cc), so both accept the same files and word
// their errors the same way. Not part of the public API.
//
// Errors are std::runtime_error("<file>: <where>: <what>"), e.g.
//   "plant.ply: line 4: unknown property type 'quaternion'"
//   "plant.ply: face 6 of 7: unexpected end of file (the data ends at byte 812)"
//   "plant.ply: vertex 0 of 1: line 8: 'zero' is not a number of the declared type"

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace avc::geometry::ply {

enum class Type { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };
enum class Format { kAscii, kBinaryLittle, kBinaryBig };

// Calls f(T{}) with T the C++ type that holds a value of type (int8_t ... double) and returns
// what it returns: the one place that maps PLY types to C++ types.
template <class F>
decltype(auto) WithCType(Type type, F&& f) {
  switch (type) {
    case Type::kInt8:
      return f(int8_t{});
    case Type::kUint8:
      return f(uint8_t{});
    case Type::kInt16:
      return f(int16_t{});
    case Type::kUint16:
      return f(uint16_t{});
    case Type::kInt32:
      return f(int32_t{});
    case Type::kUint32:
      return f(uint32_t{});
    case Type::kFloat32:
      return f(float{});
    case Type::kFloat64:
      break;
  }
  return f(double{});
}

bool IsFloat(Type type);
// Bytes in a binary body.
size_t SizeOf(Type type);
// The name written in headers: char uchar short ushort int uint float double.
std::string_view NameOf(Type type);

// The values of one property for every instance of its element, kept in the declared type (a
// float column holds 4-byte floats) and read as double, which is exact for every PLY type.
class Column {
 public:
  explicit Column(Type type) : type_(type), width_(SizeOf(type)) {}

  Type type() const { return type_; }
  size_t width() const { return width_; }  // bytes per value
  // Scalar property: one value per instance. List: the items of all instances, in order.
  size_t size() const { return used_ / width_; }
  double operator[](size_t index) const;
  // Lists only: instance i's items are [ListBegin(i), ListEnd(i)).
  size_t ListBegin(size_t instance) const { return list_starts_[instance]; }
  size_t ListEnd(size_t instance) const { return list_starts_[instance + 1]; }

  // Filling, for the reader.
  void Reserve(size_t values) {
    if (values * width_ > bytes_.size()) bytes_.resize(values * width_);
  }
  // One value of N (= width()) bytes, in the column's type and the machine's byte order.
  template <size_t N>
  void Append(const unsigned char* value) {
    // Grown by hand rather than by push_back: this runs once per value of files of millions.
    if (bytes_.size() - used_ < N) bytes_.resize(std::max(2 * bytes_.size(), used_ + N));
    std::memcpy(bytes_.data() + used_, value, N);
    used_ += N;
  }
  // One value that the column's type holds exactly.
  void AppendValue(double value);
  void StartLists(size_t instances);
  void EndList() { list_starts_.push_back(size()); }

 private:
  template <class T>
  T Load(size_t index) const {
    T value;
    std::memcpy(&value, bytes_.data() + index * sizeof(T), sizeof(T));
    return value;
  }

  Type type_;
  size_t width_;
  std::vector<unsigned char> bytes_;  // used_ of them hold values
  size_t used_ = 0;
  std::vector<size_t> list_starts_;
};

inline double Column::operator[](size_t index) const {
  return WithCType(type_, [&](auto t) -> double { return Load<decltype(t)>(index); });
}

struct Property {
  std::string name;
  Type type = Type::kFloat32;  // the item type for lists
  bool is_list = false;
  Type count_type = Type::kUint8;
};

struct Element {
  std::string name;
  size_t count = 0;
  std::vector<Property> properties;
  // One per property once the body is read (ReadBody, kept elements only); empty before.
  std::vector<Column> columns;

  // Index of the scalar property with the first of names that is declared; -1 when none is.
  int FindScalar(std::initializer_list<std::string_view> names) const;
  // Index of the list property with the first of names that is declared; -1 when none is.
  int FindList(std::initializer_list<std::string_view> names) const;
};

struct Table {
  Format format = Format::kAscii;
  std::vector<Element> elements;  // in file order
  size_t body_offset = 0;         // the byte where the body starts
  int body_first_line = 0;        // its line number, for ascii error messages

  // The first element called name; nullptr when there is none.
  const Element* Find(std::string_view name) const;
};

// Parses the header at the start of bytes (the body, if any, is not looked at). file names the
// file in error messages.
Table ParseHeader(std::string_view file, std::string_view bytes);

// Parses the body of bytes, whose header is table (from ParseHeader). The elements named in keep
// get their columns filled; the others are parsed (so their errors are reported) and dropped.
// With read_whole_body false, reading stops after the last kept element, so what follows it is
// not even looked at.
void ReadBody(std::string_view file, std::string_view bytes,
              std::initializer_list<std::string_view> keep, bool read_whole_body, Table* table);

// Indices of three scalar properties (each the first of its names that is declared), or all -1
// when any of them is missing.
std::array<int, 3> FindTriple(const Element& element, std::initializer_list<std::string_view> a,
                              std::initializer_list<std::string_view> b,
                              std::initializer_list<std::string_view> c);

// Per instance, the three scalar columns at indices as floats.
std::vector<Eigen::Vector3f> Vector3fColumns(const Element& element,
                                             const std::array<int, 3>& indices);

// Per instance RGB from red green blue (or r g b, diffuse_red ...): integer types as they are,
// float types scaled from 0..1, both rounded and clamped to 0..255. Empty when the element has
// no colour.
std::vector<Eigen::Matrix<uint8_t, 3, 1>> Colors(const Element& element);

}  // namespace avc::geometry::ply
