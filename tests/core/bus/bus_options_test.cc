#include "core/bus/bus_options.h"

#include <gtest/gtest.h>
#include <stdlib.h>

namespace avc::bus {
namespace {

class BusOptionsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    for (const char* name : {"AVC_LCM_URL", "AVC_BULK_URL", "AVC_CELL", "LCM_DEFAULT_URL"}) {
      unsetenv(name);
    }
  }
};

TEST_F(BusOptionsTest, DefaultsUseSeparateControlAndBulkGroups) {
  const BusOptions options = ResolveBusOptions({}, "svc");
  EXPECT_EQ(options.control_url, kDefaultControlUrl);
  EXPECT_EQ(options.bulk_url, kDefaultBulkUrl);
  EXPECT_NE(options.control_url, options.bulk_url);
  EXPECT_NE(options.bulk_url.find("recv_buf_size="), std::string::npos);
  EXPECT_EQ(options.cell, "cell0");
  EXPECT_EQ(options.source.rfind("svc@", 0), 0u);
}

TEST_F(BusOptionsTest, EnvironmentOverridesDefaultsAndFlagsOverrideEnvironment) {
  setenv("LCM_DEFAULT_URL", "udpm://239.255.76.67:7000?ttl=0", 1);
  EXPECT_EQ(ResolveBusOptions({}, "svc").control_url, "udpm://239.255.76.67:7000?ttl=0");
  setenv("AVC_LCM_URL", "udpm://239.255.76.67:7001?ttl=0", 1);
  setenv("AVC_CELL", "lab-2", 1);
  BusOptions options = ResolveBusOptions({}, "svc");
  EXPECT_EQ(options.control_url, "udpm://239.255.76.67:7001?ttl=0");
  EXPECT_EQ(options.cell, "lab-2");
  BusFlags flags;
  flags.lcm_url = "memq://";
  flags.cell = "c3";
  options = ResolveBusOptions(flags, "svc");
  EXPECT_EQ(options.control_url, "memq://");
  EXPECT_EQ(options.cell, "c3");
}

TEST_F(BusOptionsTest, BadCellIdIsRefusedNamingItsSource) {
  setenv("AVC_CELL", "Bad Cell", 1);
  try {
    ResolveBusOptions({}, "svc");
    FAIL() << "accepted a bad cell id";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("Bad Cell"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("AVC_CELL"), std::string::npos);
  }
}

TEST_F(BusOptionsTest, CellIdRules) {
  EXPECT_TRUE(IsValidCellId("cell0"));
  EXPECT_TRUE(IsValidCellId("a_b-9"));
  EXPECT_FALSE(IsValidCellId(""));
  EXPECT_FALSE(IsValidCellId("UPPER"));
  EXPECT_FALSE(IsValidCellId("has/slash"));
  EXPECT_FALSE(IsValidCellId("seventeen-chars-x"));
}

TEST_F(BusOptionsTest, UnknownUrlSchemeIsRefused) {
  BusFlags flags;
  flags.bulk_url = "http://example";
  EXPECT_THROW(ResolveBusOptions(flags, "svc"), std::invalid_argument);
}

}  // namespace
}  // namespace avc::bus
