#pragma once

// Builds a PLY file in memory: the header from the declared elements and properties, then the
// records, ascii (values separated by spaces, one record a line, floats in their shortest
// round-trip form so they read back exactly) or binary little endian. The one PLY writer behind
// WriteMeshPly (ply_io.cc) and WritePointCloudPly (point_cloud_io.cc). Every file says its
// lengths are in metres (the first comment). Not part of the public API.

#include <bit>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>

#include "core/geometry/ply_table.h"

namespace avc::geometry::ply {

class Writer {
 public:
  explicit Writer(bool binary);

  // Header, in file order; EndHeader before the first Put.
  void AddComment(std::string_view text);
  void AddElement(std::string_view name, size_t count);
  void AddProperty(Type type, std::string_view name);
  void AddListProperty(Type count_type, Type item_type, std::string_view name);
  // Binary: also reserves the body, so that files of millions of values grow without copies.
  void EndHeader();

  // Values of the current record, in the declared order and types.
  void Put(float value) {
    if (binary_) return AppendLittleEndian(std::bit_cast<uint32_t>(value));
    PutText(value);
  }
  void Put(uint8_t value) {
    if (binary_) return bytes_.push_back(static_cast<char>(value));
    PutText(int{value});
  }
  void Put(int32_t value) {
    if (binary_) return AppendLittleEndian(static_cast<uint32_t>(value));
    PutText(value);
  }
  void EndRecord() {
    if (!binary_) bytes_.push_back('\n');
    record_started_ = false;
  }

  // The whole file, moved out (the writer is left empty).
  std::string TakeBytes() { return std::move(bytes_); }

 private:
  // Inline: files of millions of values go through these.
  void AppendLittleEndian(uint32_t bits) {
    const char raw[4] = {static_cast<char>(bits), static_cast<char>(bits >> 8),
                         static_cast<char>(bits >> 16), static_cast<char>(bits >> 24)};
    bytes_.append(raw, 4);
  }
  // Ascii: a separating space unless first in the record, then the shortest round-trip form.
  template <class T>
  void PutText(T value);  // float or int

  bool binary_;
  bool record_started_ = false;
  std::string bytes_;
  size_t count_ = 0;                // of the element being declared
  size_t expected_body_bytes_ = 0;  // binary: the declared records (lists as triangles)
};

}  // namespace avc::geometry::ply
