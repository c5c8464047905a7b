#pragma once

// Byte fixtures from independent public sources (tests/**/fixtures/*.json): loading a file, hex
// strings and IEEE-754 bit patterns, comparing decoded fields with a case's "expect" object while
// recording which keys were compared (a field added to a fixture cannot go unchecked), and running
// every case of a file through a check chosen by its "packet" kind.

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <iomanip>
#include <iterator>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <ranges>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace avc::testing {

// SourceDir() / relative_path parsed as JSON. Throws std::runtime_error naming the file when it
// cannot be read, is not JSON or has no "cases" array.
nlohmann::json LoadFixtureFile(const std::filesystem::path& relative_path);

// "00 05 56" or "000556" -> bytes. Throws std::invalid_argument on a non-hex character or an odd
// number of digits.
std::vector<uint8_t> ParseHex(std::string_view hex);
// "0xffffffffffffffff" -> its value; at most 16 digits, else std::invalid_argument.
uint64_t ParseHexU64(std::string_view hex);
// "0x3ff0000000000000" -> the double with these bits; "0x3f800000" -> the float.
double DoubleFromBits(std::string_view hex);
float FloatFromBits(std::string_view hex);

// "name [source]" for assertion messages.
std::string CaseLabel(const nlohmann::json& fixture_case);

// A case's "expect" object that remembers the keys read.
class ExpectedFields {
 public:
  explicit ExpectedFields(const nlohmann::json& expect);

  bool Has(const std::string& key) const { return expect_.contains(key); }
  // The value of `key`, marked compared; throws std::out_of_range when absent.
  const nlohmann::json& operator[](const std::string& key);
  // Marks keys as deliberately not compared (the caller says why).
  void Acknowledge(std::initializer_list<std::string> keys);
  // Keys neither read nor acknowledged, comma-separated; empty when all were.
  std::string Unchecked() const;

 private:
  const nlohmann::json& expect_;
  std::set<std::string> read_;
};

// Whether a decoded value equals a fixture value exactly: integers without a detour through
// double, floating point bit for bit, strings, and arrays element by element.
template <class T>
bool JsonMatches(const T& got, const nlohmann::json& want) {
  if constexpr (std::is_same_v<T, bool>) {
    return want.is_boolean() && want.get<bool>() == got;
  } else if constexpr (std::is_floating_point_v<T>) {
    using Bits = std::conditional_t<sizeof(T) == 8, uint64_t, uint32_t>;
    return want.is_number() &&
           std::bit_cast<Bits>(got) == std::bit_cast<Bits>(static_cast<T>(want.get<double>()));
  } else if constexpr (std::is_integral_v<T>) {
    if (!want.is_number_integer()) return false;
    return want.is_number_unsigned() ? std::cmp_equal(got, want.get<uint64_t>())
                                     : std::cmp_equal(got, want.get<int64_t>());
  } else if constexpr (std::is_convertible_v<const T&, std::string_view>) {
    return want.is_string() && want.get<std::string>() == std::string_view(got);
  } else {
    if (!want.is_array() || want.size() != std::size(got)) return false;
    size_t i = 0;
    for (const auto& element : got) {
      if (!JsonMatches(element, want[i++])) return false;
    }
    return true;
  }
}

// The same for values the fixture gives as IEEE-754 bit strings (a "*_bits" key).
template <class T>
bool JsonBitsMatch(const T& got, const nlohmann::json& want) {
  if constexpr (std::is_floating_point_v<T>) {
    if (!want.is_string()) return false;
    using Bits = std::conditional_t<sizeof(T) == 8, uint64_t, uint32_t>;
    const std::string hex = want.get<std::string>();
    T expected;
    if constexpr (sizeof(T) == 8) {
      expected = DoubleFromBits(hex);
    } else {
      expected = FloatFromBits(hex);
    }
    return std::bit_cast<Bits>(got) == std::bit_cast<Bits>(expected);
  } else if constexpr (std::ranges::range<T> &&
                       !std::is_convertible_v<const T&, std::string_view>) {
    if (!want.is_array() || want.size() != std::size(got)) return false;
    size_t i = 0;
    for (const auto& element : got) {
      if (!JsonBitsMatch(element, want[i++])) return false;
    }
    return true;
  } else {
    return false;  // only floating-point values are written as bits
  }
}

// `value` for a failure message; floating point with every digit and its bits.
template <class T>
std::string Describe(const T& value) {
  if constexpr (std::is_floating_point_v<T>) {
    using Bits = std::conditional_t<sizeof(T) == 8, uint64_t, uint32_t>;
    std::ostringstream out;
    out << std::setprecision(std::numeric_limits<T>::max_digits10) << value << " (0x" << std::hex
        << std::setw(sizeof(T) * 2) << std::setfill('0') << std::bit_cast<Bits>(value) << ")";
    return out.str();
  } else if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) {
    return std::to_string(+value);  // uint8_t as a number, not a character
  } else if constexpr (std::ranges::range<T> &&
                       !std::is_convertible_v<const T&, std::string_view>) {
    std::string out = "{";
    for (const auto& element : value) out += (out.size() > 1 ? ", " : "") + Describe(element);
    return out + "}";
  } else {
    return ::testing::PrintToString(value);
  }
}

// EXPECTs expect[key] (or expect[key + "_bits"]) to match `got`; a key the fixture lacks fails.
template <class T>
void ExpectField(ExpectedFields& expect, const std::string& key, const T& got) {
  if (expect.Has(key)) {
    const nlohmann::json& want = expect[key];
    EXPECT_TRUE(JsonMatches(got, want))
        << key << ": decoded " << Describe(got) << ", fixture " << want.dump();
  } else if (expect.Has(key + "_bits")) {
    const nlohmann::json& want = expect[key + "_bits"];
    EXPECT_TRUE(JsonBitsMatch(got, want))
        << key << ": decoded " << Describe(got) << ", fixture " << want.dump();
  } else {
    ADD_FAILURE() << "the fixture has no \"" << key << "\"";
  }
}

// As ExpectField, but a key the fixture leaves out means the decoder must leave `got` at
// `fallback` (the struct's default): the bytes do not carry that field.
template <class T>
void ExpectFieldOr(ExpectedFields& expect, const std::string& key, const T& got,
                   const std::type_identity_t<T>& fallback) {
  if (expect.Has(key) || expect.Has(key + "_bits")) {
    ExpectField(expect, key, got);
  } else {
    EXPECT_EQ(got, fallback) << key << " is not in the fixture, so it must keep its default";
  }
}

// Checks one case; the case's expect fields are handed over for the check to compare.
using CaseCheck = std::function<void(const nlohmann::json& fixture_case, ExpectedFields& expect)>;

struct CaseChecks {
  // By the case's "packet": every kind the file may hold. An unknown kind fails the test, so a new
  // fixture cannot be ignored.
  std::map<std::string, CaseCheck> by_packet;
  // By case name: where our codec parts ways with the source on purpose, the check asserts our
  // behaviour instead. Exactly the cases marked "disagrees_with_avc" must be listed.
  std::map<std::string, CaseCheck> disagreements;
  // Which exceptions are the codec's documented refusal of bad input; empty = any.
  std::function<bool(const std::exception&)> is_refusal;
};

// Runs every case of `file` under a trace naming it and its source. A case whose expect has
// "error": true must throw; any other must not, and must leave no expect key unchecked. Returns
// the number of cases whose check ran to completion as the fixture says.
size_t CheckFixtureCases(const nlohmann::json& file, const CaseChecks& checks);

}  // namespace avc::testing
