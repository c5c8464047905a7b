#include "core/geometry/ply_writer.h"

#include <fmt/compile.h>
#include <fmt/format.h>

#include <iterator>

namespace avc::geometry::ply {

Writer::Writer(bool binary) : binary_(binary) {
  bytes_ = binary ? "ply\nformat binary_little_endian 1.0\n" : "ply\nformat ascii 1.0\n";
  // Every length AVC writes is in metres (datasets in other units are converted at import).
  AddComment("lengths in metres");
}

void Writer::AddComment(std::string_view text) {
  fmt::format_to(std::back_inserter(bytes_), "comment {}\n", text);
}

void Writer::AddElement(std::string_view name, size_t count) {
  count_ = count;
  fmt::format_to(std::back_inserter(bytes_), "element {} {}\n", name, count);
}

void Writer::AddProperty(Type type, std::string_view name) {
  expected_body_bytes_ += count_ * SizeOf(type);
  fmt::format_to(std::back_inserter(bytes_), "property {} {}\n", NameOf(type), name);
}

void Writer::AddListProperty(Type count_type, Type item_type, std::string_view name) {
  // Most lists are triangles.
  expected_body_bytes_ += count_ * (SizeOf(count_type) + 3 * SizeOf(item_type));
  fmt::format_to(std::back_inserter(bytes_), "property list {} {} {}\n", NameOf(count_type),
                 NameOf(item_type), name);
}

void Writer::EndHeader() {
  bytes_ += "end_header\n";
  if (binary_) bytes_.reserve(bytes_.size() + expected_body_bytes_);
}

template <class T>
void Writer::PutText(T value) {
  if (record_started_) bytes_.push_back(' ');
  record_started_ = true;
  char text[32];  // a float's or an int's shortest form is at most 16 characters
  const char* end = fmt::format_to(text, FMT_COMPILE("{}"), value);
  bytes_.append(text, static_cast<size_t>(end - text));
}
template void Writer::PutText(float value);
template void Writer::PutText(int value);

}  // namespace avc::geometry::ply
