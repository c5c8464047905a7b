#pragma once

// Typed point records inside a point_cloud_t (lcmtypes/avc/point_cloud_t.lcm), the layout every
// point product on the bus uses (MVS points, clusters): fields laid out in the order given, each
// at the next multiple of its size, little-endian; readers find fields by name, so a sender may
// add or reorder fields.

#include <avc/point_cloud_t.hpp>
#include <avc/point_field_t.hpp>
#include <bit>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

namespace avc::messages {

// The field types our point records use.
inline constexpr int8_t kFloat = avc::point_field_t::TYPE_FLOAT32;
inline constexpr int8_t kByte = avc::point_field_t::TYPE_UINT8;

struct FieldSpec {
  std::string name;
  int8_t datatype = kFloat;
};

// Bytes of one element of `datatype`; 0 for an unknown type.
int DatatypeBytes(int8_t datatype);

// A cloud of `num_points` zeroed records with the fields in order (frame "world").
avc::point_cloud_t MakePointCloud(const std::string& cloud_id, const std::vector<FieldSpec>& fields,
                                  size_t num_points);

// Throws std::invalid_argument naming `what` when the counts and sizes disagree with the arrays.
void CheckPointCloud(const avc::point_cloud_t& cloud, const std::string& what);

// The byte offset of the field called one of `names` with one element of `datatype`, inside the
// record. Throws std::invalid_argument naming `what` and the field when it is absent, of another
// type, or leaves the record.
int32_t FieldOffset(const avc::point_cloud_t& cloud, std::initializer_list<const char*> names,
                    int8_t datatype, const std::string& what);

// Little-endian 32-bit values at a record position.
inline void Put32(uint8_t* out, uint32_t bits) {
  for (int i = 0; i < 4; ++i) out[i] = static_cast<uint8_t>(bits >> (8 * i));
}
inline uint32_t Get32(const uint8_t* in) {
  uint32_t bits = 0;
  for (int i = 0; i < 4; ++i) bits |= static_cast<uint32_t>(in[i]) << (8 * i);
  return bits;
}
inline void PutFloat(uint8_t* out, float value) { Put32(out, std::bit_cast<uint32_t>(value)); }
inline float GetFloat(const uint8_t* in) { return std::bit_cast<float>(Get32(in)); }
inline void PutInt32(uint8_t* out, int32_t value) { Put32(out, std::bit_cast<uint32_t>(value)); }
inline int32_t GetInt32(const uint8_t* in) { return std::bit_cast<int32_t>(Get32(in)); }

}  // namespace avc::messages
