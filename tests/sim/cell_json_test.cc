#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "sim/cell/cell_truth_json.h"
#include "sim/cell/perturbation.h"
#include "tests/support/test_support.h"

namespace avc::sim {
namespace {

void ExpectIdentical(const CellTruth& a, const CellTruth& b) {
  EXPECT_EQ(a.dh.a, b.dh.a);
  EXPECT_EQ(a.dh.d, b.dh.d);
  EXPECT_EQ(a.dh.alpha, b.dh.alpha);
  EXPECT_EQ(a.dh.theta_offset, b.dh.theta_offset);
  EXPECT_EQ(a.T_base_table.matrix(), b.T_base_table.matrix());
  EXPECT_EQ(a.turntable_axis_table, b.turntable_axis_table);
  EXPECT_EQ(a.turntable_centre_table, b.turntable_centre_table);
  EXPECT_EQ(a.T_flange_cam.matrix(), b.T_flange_cam.matrix());
  EXPECT_EQ(a.intrinsics.width, b.intrinsics.width);
  EXPECT_EQ(a.intrinsics.height, b.intrinsics.height);
  EXPECT_EQ(a.intrinsics.fx, b.intrinsics.fx);
  EXPECT_EQ(a.intrinsics.fy, b.intrinsics.fy);
  EXPECT_EQ(a.intrinsics.cx, b.intrinsics.cx);
  EXPECT_EQ(a.intrinsics.cy, b.intrinsics.cy);
  EXPECT_EQ(a.intrinsics.distortion, b.intrinsics.distortion);
}

std::string ErrorOf(const nlohmann::json& json) {
  try {
    CellTruthFromJson(json);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(CellTruthJson, RoundTripsExactly) {
  for (uint32_t seed : {1u, 2u, 3u, 1000u}) {
    const CellTruth cell = PerturbedCell(seed);
    const nlohmann::json json = CellTruthToJson(cell);
    ExpectIdentical(CellTruthFromJson(nlohmann::json::parse(json.dump())), cell);
    EXPECT_EQ(CellTruthToJson(CellTruthFromJson(json)).dump(), json.dump());
  }
}

TEST(CellTruthJson, FileRoundTripIsExact) {
  testing::TempDir dir;
  const CellTruth cell = PerturbedCell(5);
  SaveCellTruth(cell, dir / "truth.json");
  ExpectIdentical(LoadCellTruth(dir / "truth.json"), cell);
  const std::string text = testing::ReadFile(dir / "truth.json");
  SaveCellTruth(LoadCellTruth(dir / "truth.json"), dir / "again.json");
  EXPECT_EQ(testing::ReadFile(dir / "again.json"), text);
}

TEST(CellTruthJson, KeysStateTheirUnits) {
  const nlohmann::json json = CellTruthToJson(NominalCell());
  EXPECT_EQ(json.at("format"), "avc-cell-truth");
  for (const char* key : {"a_m", "d_m", "alpha_rad", "theta_offset_rad"}) {
    EXPECT_TRUE(json.at("robot_dh").contains(key)) << key;
  }
  EXPECT_TRUE(json.at("T_base_table").contains("translation_m"));
  EXPECT_TRUE(json.at("T_flange_cam").contains("rotation_row_major"));
  EXPECT_TRUE(json.at("turntable").contains("centre_table_m"));
  EXPECT_TRUE(json.at("intrinsics").contains("fx_px"));
  EXPECT_EQ(json.at("robot_dh").at("d_m")[0].get<double>(), 0.089159);
}

TEST(CellTruthJson, ErrorsNameTheKey) {
  const nlohmann::json good = CellTruthToJson(PerturbedCell(9));
  nlohmann::json missing = good;
  missing["intrinsics"].erase("fy_px");
  EXPECT_NE(ErrorOf(missing).find("cell.intrinsics.fy_px"), std::string::npos) << ErrorOf(missing);
  nlohmann::json short_array = good;
  short_array["robot_dh"]["alpha_rad"].erase(5);
  EXPECT_NE(ErrorOf(short_array).find("cell.robot_dh.alpha_rad"), std::string::npos);
  nlohmann::json text_number = good;
  text_number["turntable"]["centre_table_m"][1] = "0.1";
  EXPECT_NE(ErrorOf(text_number).find("cell.turntable.centre_table_m[1]"), std::string::npos);
  nlohmann::json sheared = good;
  sheared["T_base_table"]["rotation_row_major"][0][1] = 0.5;
  EXPECT_NE(ErrorOf(sheared).find("T_base_table"), std::string::npos);
  nlohmann::json wrong_format = good;
  wrong_format["format"] = "something-else";
  EXPECT_NE(ErrorOf(wrong_format).find("format"), std::string::npos);
  nlohmann::json wrong_version = good;
  wrong_version["version"] = 2;
  EXPECT_NE(ErrorOf(wrong_version).find("version 2"), std::string::npos);
  EXPECT_NE(ErrorOf(nlohmann::json::array()).find("not an object"), std::string::npos);
}

TEST(CellTruthJson, FileErrorsNameThePath) {
  testing::TempDir dir;
  try {
    LoadCellTruth(dir / "absent.json");
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("absent.json"), std::string::npos);
  }
  testing::WriteFile(dir / "broken.json", "{\"format\": ");
  try {
    LoadCellTruth(dir / "broken.json");
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("broken.json"), std::string::npos);
  }
  CellTruth invalid = NominalCell();
  invalid.intrinsics.fx = 0;
  EXPECT_THROW(SaveCellTruth(invalid, dir / "invalid.json"), std::runtime_error);
  EXPECT_THROW(SaveCellTruth(NominalCell(), dir / "no_such_dir" / "x.json"), std::runtime_error);
}

}  // namespace
}  // namespace avc::sim
