// lcmtypes/CHANNELS.md is the documented table of channels; core/bus/channels.h is what the code
// uses. They must agree both ways.

#include "core/bus/channels.h"

#include <gtest/gtest.h>

#include <regex>
#include <set>

#include "tests/support/test_support.h"

namespace avc {
namespace {

std::set<std::string> ChannelsInDoc() {
  const std::string doc = testing::ReadFile(testing::SourceDir() / "lcmtypes" / "CHANNELS.md");
  const std::regex row(R"(\n\| `([A-Z_/]+)` \|)");
  std::set<std::string> names;
  for (auto it = std::sregex_iterator(doc.begin(), doc.end(), row); it != std::sregex_iterator();
       ++it) {
    names.insert((*it)[1]);
  }
  return names;
}

TEST(Channels, DocumentAndHeaderAgree) {
  std::set<std::string> in_code;
  for (auto name : channels::kAll) in_code.insert(std::string(name));
  EXPECT_EQ(in_code.size(), channels::kAll.size()) << "a channel name is listed twice";
  EXPECT_EQ(ChannelsInDoc(), in_code);
}

TEST(Channels, FitLcmLimitWithLongestCellPrefix) {
  for (auto name : channels::kAll) {
    EXPECT_LE(16 + 1 + name.size(), 63u) << name;
  }
}

}  // namespace
}  // namespace avc
