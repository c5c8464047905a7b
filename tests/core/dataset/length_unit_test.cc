// The unit of an imported dataset: told from its cameras' distances, declared, or given, and
// refused when it puts the cameras where no scanning set-up has them.

#include "core/dataset/length_unit.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

namespace avc::dataset {
namespace {

// A ring of cameras `distance` from the origin, looking at it.
std::vector<camera::Camera> Ring(double distance) {
  std::vector<camera::Camera> cameras;
  for (int i = 0; i < 8; ++i) {
    const double angle = i * M_PI / 4;
    camera::Camera camera;
    camera.intrinsics = {640, 480, 500, 500, 319.5, 239.5, {}};
    const Eigen::Vector3d centre =
        distance * Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.3).normalized();
    const Eigen::Vector3d z = (-centre).normalized();
    const Eigen::Vector3d x = z.cross(Eigen::Vector3d::UnitZ()).normalized();
    Eigen::Matrix3d r;
    r << x.transpose(), z.cross(x).transpose(), z.transpose();
    camera.T_cam_world.linear() = r;
    camera.T_cam_world.translation() = -r * centre;
    cameras.push_back(camera);
  }
  return cameras;
}

UnitDecision Decide(double distance, LengthUnit requested = LengthUnit::kAuto,
                    LengthUnit declared = LengthUnit::kAuto) {
  return DecideLengthUnit(Ring(distance), requested, declared, "index.json", "scans/plant");
}

TEST(LengthUnit, NamesParseAndScale) {
  for (LengthUnit unit : {LengthUnit::kAuto, LengthUnit::kMetre, LengthUnit::kMillimetre}) {
    EXPECT_EQ(ParseLengthUnit(LengthUnitName(unit)), unit);
  }
  EXPECT_THROW(ParseLengthUnit("cm"), std::invalid_argument);
  EXPECT_DOUBLE_EQ(MetresPerUnit(LengthUnit::kMillimetre), 1e-3);
  EXPECT_THROW(MetresPerUnit(LengthUnit::kAuto), std::invalid_argument);
}

TEST(LengthUnit, TellsMetresFromMillimetresByTheCamerasDistance) {
  const UnitDecision metres = Decide(0.45);
  EXPECT_EQ(metres.unit, LengthUnit::kMetre);
  EXPECT_NEAR(metres.camera_distance, 0.45, 1e-9);
  EXPECT_NE(metres.how.find("automatic"), std::string::npos) << metres.how;
  const UnitDecision millimetres = Decide(450);
  EXPECT_EQ(millimetres.unit, LengthUnit::kMillimetre);
  EXPECT_NE(millimetres.how.find("0.45 m"), std::string::npos) << millimetres.how;
}

TEST(LengthUnit, TheUsersUnitWinsOverTheDatasetsWhichWinsOverTheGuess) {
  EXPECT_EQ(Decide(0.45, LengthUnit::kAuto, LengthUnit::kMetre).unit, LengthUnit::kMetre);
  const UnitDecision declared = Decide(450, LengthUnit::kAuto, LengthUnit::kMillimetre);
  EXPECT_NE(declared.how.find("from index.json"), std::string::npos) << declared.how;
  const UnitDecision requested = Decide(450, LengthUnit::kMillimetre, LengthUnit::kMetre);
  EXPECT_EQ(requested.unit, LengthUnit::kMillimetre);
  EXPECT_NE(requested.how.find("from --units"), std::string::npos) << requested.how;
}

TEST(LengthUnit, RefusesAUnitThatPutsTheCamerasWhereNoCellHasThem) {
  try {
    Decide(450, LengthUnit::kAuto, LengthUnit::kMetre);
    FAIL() << "450 m from the plant was accepted";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("scans/plant: index.json says m"), std::string::npos)
        << error.what();
  }
  // 30 units: 30 m is too far, 30 mm too near.
  try {
    Decide(30);
    FAIL() << "an implausible scale was accepted";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("pass --units m or --units mm"), std::string::npos)
        << error.what();
  }
  EXPECT_THROW(DecideLengthUnit({}, LengthUnit::kAuto, LengthUnit::kAuto, "", "x"),
               std::runtime_error);
}

}  // namespace
}  // namespace avc::dataset
