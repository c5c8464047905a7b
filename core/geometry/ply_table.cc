#include "core/geometry/ply_table.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include "core/geometry/mesh_io_internal.h"

namespace avc::geometry::ply {
namespace {

using mesh_io::LineReader;
using mesh_io::ParseDouble;
using mesh_io::ParseFloat;
using mesh_io::ParseInt;
using mesh_io::SplitTokens;

// Throws std::runtime_error("<file>: <message>").
template <class... Args>
[[noreturn]] void Fail(std::string_view file, fmt::format_string<Args...> format, Args&&... args) {
  throw std::runtime_error(
      fmt::format("{}: {}", file, fmt::format(format, std::forward<Args>(args)...)));
}

// Longer than this, the list is taken for corrupt data rather than a real polygon or list.
constexpr double kMaxListLength = 1e6;

// Header names of the types: the PLY 1.0 name (written) and the sized alias (also read).
struct TypeName {
  std::string_view name, alias;
  Type type;
};
constexpr TypeName kTypeNames[] = {
    {"char", "int8", Type::kInt8},        {"uchar", "uint8", Type::kUint8},
    {"short", "int16", Type::kInt16},     {"ushort", "uint16", Type::kUint16},
    {"int", "int32", Type::kInt32},       {"uint", "uint32", Type::kUint32},
    {"float", "float32", Type::kFloat32}, {"double", "float64", Type::kFloat64}};

bool ParseType(std::string_view name, Type* type) {
  for (const TypeName& entry : kTypeNames) {
    if (name == entry.name || name == entry.alias) {
      *type = entry.type;
      return true;
    }
  }
  return false;
}

std::string Shorten(std::string_view text) {
  return std::string(text.size() > 40 ? text.substr(0, 40) : text);
}

int FindProperty(const Element& element, std::initializer_list<std::string_view> names,
                 bool is_list) {
  for (std::string_view name : names) {
    for (size_t i = 0; i < element.properties.size(); ++i) {
      if (element.properties[i].is_list == is_list && element.properties[i].name == name) {
        return static_cast<int>(i);
      }
    }
  }
  return -1;
}

// Whether the type holds value (an integer read from an ascii body).
bool Fits(Type type, int64_t value) {
  return WithCType(type, [value](auto t) {
    using T = decltype(t);
    if constexpr (std::is_integral_v<T>) {
      return value >= std::numeric_limits<T>::min() && value <= std::numeric_limits<T>::max();
    } else {
      return true;
    }
  });
}

template <class T>
void AppendAs(double value, Column* column) {
  const T typed = static_cast<T>(value);
  unsigned char raw[sizeof(T)];
  std::memcpy(raw, &typed, sizeof(T));
  column->Append<sizeof(T)>(raw);
}

// Values of an ascii body, one whitespace-separated token at a time. On failure Read and Copy
// return false and error() says why (with the line number).
class AsciiSource {
 public:
  AsciiSource(std::string_view body, int first_line) : body_(body), line_(first_line) {}

  // The least number of bytes one value takes (a digit and a separator, or the last digit).
  static size_t MinSize(Type /*type*/) { return 1; }
  // Bytes left.
  size_t size() const { return body_.size() - pos_; }

  bool Read(Type type, double* value) {
    while (pos_ < body_.size() && std::isspace(static_cast<unsigned char>(body_[pos_]))) {
      if (body_[pos_] == '\n') ++line_;
      ++pos_;
    }
    if (pos_ >= body_.size()) {
      error_ = "unexpected end of file";
      return false;
    }
    const size_t start = pos_;
    while (pos_ < body_.size() && !std::isspace(static_cast<unsigned char>(body_[pos_]))) ++pos_;
    const std::string_view token = body_.substr(start, pos_ - start);
    bool ok = false;
    if (type == Type::kFloat32) {
      float f = 0;  // parsed as float, not via double, so shortest forms round-trip bit-exact
      ok = ParseFloat(token, &f);
      *value = f;
    } else if (type == Type::kFloat64) {
      ok = ParseDouble(token, value);
    } else {
      int64_t i = 0;
      ok = ParseInt(token, &i) && Fits(type, i);
      *value = static_cast<double>(i);
    }
    if (!ok) {
      error_ =
          fmt::format("line {}: '{}' is not a number of the declared type", line_, Shorten(token));
    }
    return ok;
  }

  // Reads one value of the column's type onto its end.
  bool Copy(Column* column) {
    double value = 0;
    if (!Read(column->type(), &value)) return false;
    column->AppendValue(value);
    return true;
  }

  const std::string& error() const { return error_; }

 private:
  std::string_view body_;
  size_t pos_ = 0;
  int line_;
  std::string error_;
};

// Values of a binary body (little or big endian).
class BinarySource {
 public:
  BinarySource(std::string_view bytes, size_t offset, bool big_endian)
      : bytes_(bytes),
        pos_(offset),
        swap_(big_endian != (std::endian::native == std::endian::big)) {}

  static size_t MinSize(Type type) { return SizeOf(type); }
  // Bytes left.
  size_t size() const { return bytes_.size() - pos_; }

  bool Read(Type type, double* value) {
    return WithCType(type, [&](auto t) { return Take<decltype(t)>(value); });
  }

  // Copies one value of the column's type onto its end: no conversion, at most a byte swap.
  bool Copy(Column* column) {
    switch (column->width()) {
      case 1:
        return CopyBytes<1>(column);
      case 2:
        return CopyBytes<2>(column);
      case 4:
        return CopyBytes<4>(column);
      default:
        return CopyBytes<8>(column);
    }
  }

  const std::string& error() const { return error_; }

 private:
  template <class T>
  bool Take(double* value) {
    if (bytes_.size() - pos_ < sizeof(T)) return Truncated();
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, bytes_.data() + pos_, sizeof(T));
    if (swap_) std::reverse(raw, raw + sizeof(T));
    pos_ += sizeof(T);
    *value = static_cast<double>(std::bit_cast<T>(raw));
    return true;
  }

  template <size_t N>
  bool CopyBytes(Column* column) {
    if (bytes_.size() - pos_ < N) return Truncated();
    unsigned char raw[N];
    std::memcpy(raw, bytes_.data() + pos_, N);
    if (swap_) std::reverse(raw, raw + N);
    pos_ += N;
    column->Append<N>(raw);
    return true;
  }

  bool Truncated() {
    error_ = fmt::format("unexpected end of file (the data ends at byte {})", bytes_.size());
    return false;
  }

  std::string_view bytes_;
  size_t pos_;
  bool swap_;
  std::string error_;
};

// Reads the instances of one element after another from a Source.
template <class Source>
class BodyReader {
 public:
  BodyReader(std::string_view file, Source source) : file_(file), source_(std::move(source)) {}

  void Read(Element* element, bool keep) {
    if (keep) PrepareColumns(element);
    for (size_t i = 0; i < element->count; ++i) {
      for (size_t p = 0; p < element->properties.size(); ++p) {
        const Property& property = element->properties[p];
        if (!property.is_list) {
          if (keep) {
            Copy(*element, i, &element->columns[p]);
          } else {
            Value(*element, i, property.type);
          }
          continue;
        }
        const double length = Value(*element, i, property.count_type);
        if (!(length >= 0 && length <= kMaxListLength)) {
          Fail(file_, "{} {} of {}: bad list length {}", element->name, i, element->count, length);
        }
        const auto items = static_cast<size_t>(length);
        if (!keep) {
          for (size_t k = 0; k < items; ++k) Value(*element, i, property.type);
          continue;
        }
        Column& column = element->columns[p];
        // Lists of one element are mostly of one length (triangles): reserve by the first.
        if (i == 0 && items > 0) {
          column.Reserve(std::min(element->count, MaxValues(property.type) / items + 1) * items);
        }
        for (size_t k = 0; k < items; ++k) Copy(*element, i, &column);
        column.EndList();
      }
    }
  }

 private:
  double Value(const Element& element, size_t index, Type type) {
    double value = 0;
    if (!source_.Read(type, &value)) Failed(element, index);
    return value;
  }

  void Copy(const Element& element, size_t index, Column* column) {
    if (!source_.Copy(column)) Failed(element, index);
  }

  [[noreturn]] void Failed(const Element& element, size_t index) {
    Fail(file_, "{} {} of {}: {}", element.name, index, element.count, source_.error());
  }

  // Reserves for as many instances as the rest of the body could hold, so that a corrupt count
  // cannot make us allocate gigabytes.
  void PrepareColumns(Element* element) {
    size_t min_instance_size = 0;
    for (const Property& property : element->properties) {
      min_instance_size += Source::MinSize(property.is_list ? property.count_type : property.type);
    }
    const size_t fit = source_.size() / std::max<size_t>(min_instance_size, 1) + 1;
    const size_t reserve = std::min(element->count, fit);
    element->columns.clear();
    for (const Property& property : element->properties) {
      Column& column = element->columns.emplace_back(property.type);
      if (property.is_list) {
        column.StartLists(reserve);
      } else {
        column.Reserve(reserve);
      }
    }
  }

  // As many values of type as the rest of the body could hold.
  size_t MaxValues(Type type) const { return source_.size() / Source::MinSize(type) + 1; }

  std::string_view file_;
  Source source_;
};

template <class Source>
void ReadElements(std::string_view file, Source source,
                  std::initializer_list<std::string_view> keep, size_t end, Table* table) {
  BodyReader<Source> reader(file, std::move(source));
  for (size_t e = 0; e < end; ++e) {
    Element& element = table->elements[e];
    const bool kept = std::find(keep.begin(), keep.end(), element.name) != keep.end();
    reader.Read(&element, kept);
  }
}

uint8_t ColorChannel(Type type, double value) {
  const double scaled = IsFloat(type) ? value * 255.0 : value;
  if (!(scaled > 0)) return 0;  // also NaN
  if (scaled >= 255) return 255;
  return static_cast<uint8_t>(std::lround(scaled));
}

}  // namespace

bool IsFloat(Type type) { return type == Type::kFloat32 || type == Type::kFloat64; }

size_t SizeOf(Type type) {
  return WithCType(type, [](auto t) { return sizeof(t); });
}

std::string_view NameOf(Type type) {
  for (const TypeName& entry : kTypeNames) {
    if (entry.type == type) return entry.name;
  }
  return "";
}

void Column::AppendValue(double value) {
  WithCType(type_, [&](auto t) { AppendAs<decltype(t)>(value, this); });
}

void Column::StartLists(size_t instances) {
  list_starts_.reserve(instances + 1);
  list_starts_.push_back(0);
}

int Element::FindScalar(std::initializer_list<std::string_view> names) const {
  return FindProperty(*this, names, false);
}

int Element::FindList(std::initializer_list<std::string_view> names) const {
  return FindProperty(*this, names, true);
}

const Element* Table::Find(std::string_view name) const {
  for (const Element& element : elements) {
    if (element.name == name) return &element;
  }
  return nullptr;
}

Table ParseHeader(std::string_view file, std::string_view bytes) {
  LineReader lines(bytes);
  std::string_view line;
  lines.Next(&line);
  if (line != "ply")
    Fail(file, "line 1: not a PLY file (expected 'ply', found '{}')", Shorten(line));
  Table table;
  bool have_format = false;
  while (lines.Next(&line)) {
    const int n = lines.line_number();
    const std::vector<std::string_view> tokens = SplitTokens(line);
    if (tokens.empty()) continue;
    const std::string_view keyword = tokens[0];
    if (keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "end_header") {
      if (!have_format) Fail(file, "line {}: header has no format line", n);
      table.body_offset = lines.offset();
      table.body_first_line = n + 1;
      return table;
    }
    if (keyword == "format") {
      if (tokens.size() != 3) Fail(file, "line {}: expected 'format <type> 1.0'", n);
      if (tokens[1] == "ascii") {
        table.format = Format::kAscii;
      } else if (tokens[1] == "binary_little_endian") {
        table.format = Format::kBinaryLittle;
      } else if (tokens[1] == "binary_big_endian") {
        table.format = Format::kBinaryBig;
      } else {
        Fail(file, "line {}: unknown format '{}'", n, Shorten(tokens[1]));
      }
      have_format = true;
    } else if (keyword == "element") {
      int64_t count = 0;
      if (tokens.size() != 3 || !ParseInt(tokens[2], &count) || count < 0) {
        Fail(file, "line {}: expected 'element <name> <count>'", n);
      }
      table.elements.push_back({std::string(tokens[1]), static_cast<size_t>(count), {}, {}});
    } else if (keyword == "property") {
      if (table.elements.empty()) Fail(file, "line {}: property before any element", n);
      Property property;
      if (tokens.size() == 5 && tokens[1] == "list") {
        property.is_list = true;
        if (!ParseType(tokens[2], &property.count_type) || IsFloat(property.count_type) ||
            !ParseType(tokens[3], &property.type)) {
          Fail(file, "line {}: bad list property types '{} {}'", n, Shorten(tokens[2]),
               Shorten(tokens[3]));
        }
        property.name = tokens[4];
      } else if (tokens.size() == 3) {
        if (!ParseType(tokens[1], &property.type)) {
          Fail(file, "line {}: unknown property type '{}'", n, Shorten(tokens[1]));
        }
        property.name = tokens[2];
      } else {
        Fail(file, "line {}: expected 'property <type> <name>' or 'property list ...'", n);
      }
      table.elements.back().properties.push_back(std::move(property));
    } else {
      Fail(file, "line {}: unexpected '{}' in the header", n, Shorten(keyword));
    }
  }
  Fail(file, "header has no end_header line");
}

void ReadBody(std::string_view file, std::string_view bytes,
              std::initializer_list<std::string_view> keep, bool read_whole_body, Table* table) {
  size_t end = read_whole_body ? table->elements.size() : 0;
  for (size_t e = end; e < table->elements.size(); ++e) {
    if (std::find(keep.begin(), keep.end(), table->elements[e].name) != keep.end()) end = e + 1;
  }
  if (table->format == Format::kAscii) {
    ReadElements(file, AsciiSource(bytes.substr(table->body_offset), table->body_first_line), keep,
                 end, table);
  } else {
    const bool big_endian = table->format == Format::kBinaryBig;
    ReadElements(file, BinarySource(bytes, table->body_offset, big_endian), keep, end, table);
  }
}

std::array<int, 3> FindTriple(const Element& element, std::initializer_list<std::string_view> a,
                              std::initializer_list<std::string_view> b,
                              std::initializer_list<std::string_view> c) {
  const std::array<int, 3> indices = {element.FindScalar(a), element.FindScalar(b),
                                      element.FindScalar(c)};
  if (indices[0] < 0 || indices[1] < 0 || indices[2] < 0) return {-1, -1, -1};
  return indices;
}

std::vector<Eigen::Vector3f> Vector3fColumns(const Element& element,
                                             const std::array<int, 3>& indices) {
  const Column& a = element.columns[indices[0]];
  const Column& b = element.columns[indices[1]];
  const Column& c = element.columns[indices[2]];
  std::vector<Eigen::Vector3f> vectors(a.size());
  for (size_t i = 0; i < vectors.size(); ++i) {
    vectors[i] = Eigen::Vector3f(static_cast<float>(a[i]), static_cast<float>(b[i]),
                                 static_cast<float>(c[i]));
  }
  return vectors;
}

std::vector<Eigen::Matrix<uint8_t, 3, 1>> Colors(const Element& element) {
  const std::array<int, 3> rgb =
      FindTriple(element, {"red", "r", "diffuse_red"}, {"green", "g", "diffuse_green"},
                 {"blue", "b", "diffuse_blue"});
  if (rgb[0] < 0) return {};
  std::vector<Eigen::Matrix<uint8_t, 3, 1>> colors(element.columns[rgb[0]].size());
  for (int k = 0; k < 3; ++k) {
    const Column& column = element.columns[rgb[k]];
    for (size_t i = 0; i < colors.size(); ++i)
      colors[i][k] = ColorChannel(column.type(), column[i]);
  }
  return colors;
}

}  // namespace avc::geometry::ply
