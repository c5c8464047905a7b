#include "tests/support/fixture_file.h"

#include <bit>
#include <stdexcept>

#include "tests/support/test_support.h"

namespace avc::testing {
namespace {

int HexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::string_view WithoutPrefix(std::string_view hex) {
  if (hex.starts_with("0x") || hex.starts_with("0X")) hex.remove_prefix(2);
  return hex;
}

}  // namespace

nlohmann::json LoadFixtureFile(const std::filesystem::path& relative_path) {
  const std::filesystem::path path = SourceDir() / relative_path;
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(ReadFile(path));
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path.string() + ": not JSON: " + e.what());
  }
  if (!json.contains("cases") || !json["cases"].is_array()) {
    throw std::runtime_error(path.string() + ": no \"cases\" array");
  }
  return json;
}

std::vector<uint8_t> ParseHex(std::string_view hex) {
  std::vector<uint8_t> bytes;
  int high = -1;
  for (const char c : hex) {
    if (c == ' ') continue;
    const int digit = HexDigit(c);
    if (digit < 0) throw std::invalid_argument("not a hex digit in '" + std::string(hex) + "'");
    if (high < 0) {
      high = digit;
    } else {
      bytes.push_back(static_cast<uint8_t>(high << 4 | digit));
      high = -1;
    }
  }
  if (high >= 0)
    throw std::invalid_argument("odd number of hex digits: '" + std::string(hex) + "'");
  return bytes;
}

uint64_t ParseHexU64(std::string_view hex) {
  const std::string_view digits = WithoutPrefix(hex);
  if (digits.empty() || digits.size() > 16) {
    throw std::invalid_argument("not a 64-bit hex value: '" + std::string(hex) + "'");
  }
  uint64_t value = 0;
  for (const char c : digits) {
    const int digit = HexDigit(c);
    if (digit < 0) throw std::invalid_argument("not a hex digit in '" + std::string(hex) + "'");
    value = value << 4 | static_cast<uint64_t>(digit);
  }
  return value;
}

double DoubleFromBits(std::string_view hex) {
  if (WithoutPrefix(hex).size() != 16) {
    throw std::invalid_argument("a double needs 16 hex digits: '" + std::string(hex) + "'");
  }
  return std::bit_cast<double>(ParseHexU64(hex));
}

float FloatFromBits(std::string_view hex) {
  if (WithoutPrefix(hex).size() != 8) {
    throw std::invalid_argument("a float needs 8 hex digits: '" + std::string(hex) + "'");
  }
  return std::bit_cast<float>(static_cast<uint32_t>(ParseHexU64(hex)));
}

std::string CaseLabel(const nlohmann::json& fixture_case) {
  return fixture_case.value("name", std::string("<unnamed>")) + " [" +
         fixture_case.value("source", std::string("<no source>")) + "]";
}

ExpectedFields::ExpectedFields(const nlohmann::json& expect) : expect_(expect) {
  if (!expect_.is_object()) throw std::invalid_argument("\"expect\" is not a JSON object");
}

const nlohmann::json& ExpectedFields::operator[](const std::string& key) {
  if (!expect_.contains(key)) throw std::out_of_range("expect has no \"" + key + "\"");
  read_.insert(key);
  return expect_.at(key);
}

void ExpectedFields::Acknowledge(std::initializer_list<std::string> keys) {
  read_.insert(keys.begin(), keys.end());
}

std::string ExpectedFields::Unchecked() const {
  std::string unchecked;
  for (const auto& [key, value] : expect_.items()) {
    if (read_.count(key) != 0) continue;
    unchecked += (unchecked.empty() ? "" : ", ") + key;
  }
  return unchecked;
}

namespace {

// Whether the current test recorded a failure since it had `parts_before` results.
bool FailedSince(int parts_before) {
  const ::testing::TestResult* result =
      ::testing::UnitTest::GetInstance()->current_test_info()->result();
  for (int i = parts_before; i < result->total_part_count(); ++i) {
    if (result->GetTestPartResult(i).failed()) return true;
  }
  return false;
}

// One case: true when it behaved as the fixture says.
bool CheckCase(const nlohmann::json& fixture_case, const CaseChecks& checks) {
  const std::string kind = fixture_case.value("packet", std::string());
  const auto by_packet = checks.by_packet.find(kind);
  if (by_packet == checks.by_packet.end()) {
    ADD_FAILURE() << "unknown packet kind '" << kind << "': add a check for it";
    return false;
  }
  const auto disagreement = checks.disagreements.find(fixture_case.value("name", std::string()));
  const bool listed = disagreement != checks.disagreements.end();
  if (fixture_case.contains("disagrees_with_avc") != listed) {
    ADD_FAILURE() << (listed ? "listed as a disagreement but the fixture has no disagrees_with_avc"
                             : "the fixture says disagrees_with_avc but the test does not assert "
                               "our behaviour for it");
    return false;
  }
  const int parts_before =
      ::testing::UnitTest::GetInstance()->current_test_info()->result()->total_part_count();
  ExpectedFields expect(fixture_case.at("expect"));
  const bool must_refuse = expect.Has("error") && expect["error"].get<bool>();
  const CaseCheck& check = listed ? disagreement->second : by_packet->second;
  try {
    check(fixture_case, expect);
    if (must_refuse) ADD_FAILURE() << "accepted, but the fixture says it must be refused";
    // After a refusal the fields past it cannot be compared, so this is for accepted cases.
    EXPECT_EQ(expect.Unchecked(), "") << "expect keys the test never compared";
  } catch (const std::exception& e) {
    if (!must_refuse || (checks.is_refusal && !checks.is_refusal(e))) {
      ADD_FAILURE() << "threw: " << e.what();
    }
  }
  return !FailedSince(parts_before);
}

}  // namespace

size_t CheckFixtureCases(const nlohmann::json& file, const CaseChecks& checks) {
  size_t passed = 0;
  for (const nlohmann::json& fixture_case : file.at("cases")) {
    SCOPED_TRACE(CaseLabel(fixture_case));
    if (CheckCase(fixture_case, checks)) ++passed;
  }
  return passed;
}

}  // namespace avc::testing
