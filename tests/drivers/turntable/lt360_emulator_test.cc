// The LT360 emulator seen through a raw serial port: grammar (case, CR or NUL terminators,
// unknown commands), motion at the set speed on the stepped clock, 0.1 deg quantisation and the
// seeded true-angle error model.

#include "sim/emulators/lt360/lt360_emulator.h"

#include <gtest/gtest.h>

#include <cmath>

#include "drivers/turntable/serial_port.h"

namespace avc::sim {
namespace {

using std::chrono::milliseconds;
using turntable::SerialPort;

std::string Ask(SerialPort& port, const std::string& command, char terminator = '\r') {
  port.WriteLine(command, terminator, milliseconds(500));
  return port.ReadLine(milliseconds(500)).value_or("(no reply)");
}

TEST(Lt360Emulator, SpeaksTheTableGrammarWithCrOrNul) {
  Lt360EmulatorOptions options;
  options.start_deg = 359.96;  // rounds to 0.0: reported angles stay in [0, 360)
  Lt360Emulator emulator(options, std::make_shared<SteppedEmulatorClock>(0));
  SerialPort port(emulator.device_path(), 115200);
  EXPECT_EQ(Ask(port, "CP"), "+0.0");
  EXPECT_EQ(Ask(port, "cp", '\0'), "+0.0");
  EXPECT_EQ(Ask(port, " mv "), "NO");
  EXPECT_EQ(Ask(port, "JUMP 5"), "ERR");
  EXPECT_EQ(Ask(port, "SPEED -3"), "ERR");
  EXPECT_EQ(Ask(port, "speed 45.5"), "OK");
  EXPECT_DOUBLE_EQ(emulator.speed_deg_s(), 45.5);
  EXPECT_EQ(emulator.commands_served(), 6);
}

TEST(Lt360Emulator, WaitsSilentlyForATerminator) {
  Lt360Emulator emulator({});
  SerialPort port(emulator.device_path(), 9600);
  port.WriteLine("C", 'P', milliseconds(500));  // "CP" without CR or NUL
  EXPECT_FALSE(port.ReadLine(milliseconds(100)));
  port.WriteLine("", '\r', milliseconds(500));  // now terminated
  EXPECT_EQ(port.ReadLine(milliseconds(500)), "+0.0");
}

TEST(Lt360Emulator, MovesAtItsSpeedAndQuantisesToATenth) {
  Lt360EmulatorOptions options;
  options.speed_deg_s = 10;
  auto clock = std::make_shared<SteppedEmulatorClock>(0);  // the test moves time itself
  Lt360Emulator emulator(options, clock);
  SerialPort port(emulator.device_path(), 9600);
  EXPECT_EQ(Ask(port, "GO 90.0"), "OK");
  clock->Advance(2.346);
  EXPECT_EQ(Ask(port, "CP"), "+23.5");  // 23.46 deg, rounded to the nearest tenth
  EXPECT_EQ(Ask(port, "MV"), "CCW");
  clock->Advance(10);
  EXPECT_EQ(Ask(port, "CP"), "+90.0");
  EXPECT_EQ(Ask(port, "MV"), "NO");
  // The short way from 90 to 10 is clockwise.
  EXPECT_EQ(Ask(port, "GO 10.0"), "OK");
  clock->Advance(1);
  EXPECT_EQ(Ask(port, "MV"), "CW");
  EXPECT_EQ(Ask(port, "CP"), "+80.0");
  EXPECT_EQ(Ask(port, "STOP"), "OK");
  clock->Advance(5);
  EXPECT_EQ(Ask(port, "CP"), "+80.0");
  EXPECT_EQ(Ask(port, "MV"), "NO");
}

TEST(Lt360Emulator, AcceleratesAndDeceleratesOnATrapezoid) {
  // 10 deg/s reached after 0.5 s (2.5 deg); a 90 deg move ends after 9.5 s.
  EXPECT_DOUBLE_EQ(TravelledDeg(90, 10, 20, 0.25), 0.625);
  EXPECT_DOUBLE_EQ(TravelledDeg(90, 10, 20, 0.5), 2.5);
  EXPECT_DOUBLE_EQ(TravelledDeg(90, 10, 20, 5), 47.5);
  EXPECT_DOUBLE_EQ(TravelledDeg(90, 10, 20, 9), 87.5);
  EXPECT_DOUBLE_EQ(TravelledDeg(90, 10, 20, 9.5), 90);
  EXPECT_DOUBLE_EQ(TravelledDeg(90, 10, 20, 100), 90);
  // Too short for full speed: a triangle that still ends exactly at the distance.
  const double half_s = std::sqrt(1.0 / 20);
  EXPECT_DOUBLE_EQ(TravelledDeg(1, 10, 20, half_s), 0.5);
  EXPECT_DOUBLE_EQ(TravelledDeg(1, 10, 20, 2 * half_s), 1);
  double previous = 0;
  for (double t = 0; t < 11; t += 0.01) {
    const double now = TravelledDeg(90, 10, 20, t);
    EXPECT_GE(now, previous);
    EXPECT_LE(now - previous, 10 * 0.01 + 1e-9);  // never faster than the set speed
    previous = now;
  }
  EXPECT_DOUBLE_EQ(TravelledDeg(90, 10, 0, 3), 30);  // no acceleration: constant speed

  Lt360EmulatorOptions options;
  options.speed_deg_s = 10;
  options.accel_deg_s2 = 20;
  auto clock = std::make_shared<SteppedEmulatorClock>(0);
  Lt360Emulator emulator(options, clock);
  SerialPort port(emulator.device_path(), 9600);
  EXPECT_EQ(Ask(port, "GO 90.0"), "OK");
  clock->Advance(0.5);
  EXPECT_EQ(Ask(port, "CP"), "+2.5");
  clock->Advance(9);
  EXPECT_EQ(Ask(port, "CP"), "+90.0");
  EXPECT_EQ(Ask(port, "MV"), "NO");
}

TEST(Lt360Emulator, TrueAngleFollowsTheErrorModel) {
  Lt360EmulatorOptions options;
  options.offset_deg = 0.5;
  options.scale_error = 0.01;
  auto clock = std::make_shared<SteppedEmulatorClock>(100);  // every move completes at once
  Lt360Emulator emulator(options, clock);
  SerialPort port(emulator.device_path(), 9600);
  Ask(port, "GO 100.0");
  Ask(port, "CP");
  EXPECT_EQ(emulator.ReportedTenths(), 1000);
  EXPECT_NEAR(emulator.TrueAngleDeg(), 100 * 1.01 + 0.5, 1e-9);

  // Random error: per move, seeded, so two emulators with one seed agree and differ from another.
  auto true_angles = [](uint64_t seed) {
    Lt360EmulatorOptions noisy;
    noisy.sigma_deg = 0.1;
    noisy.seed = seed;
    Lt360Emulator table(noisy, std::make_shared<SteppedEmulatorClock>(100));
    SerialPort serial(table.device_path(), 9600);
    std::vector<double> angles;
    double sum_sq = 0;
    for (int i = 1; i <= 40; ++i) {
      Ask(serial, "GO " + std::to_string(i * 5) + ".0");
      Ask(serial, "CP");
      angles.push_back(table.TrueAngleDeg());
      sum_sq += std::pow(table.TrueAngleDeg() - i * 5, 2);
    }
    angles.push_back(std::sqrt(sum_sq / 40));
    return angles;
  };
  const std::vector<double> a = true_angles(3);
  EXPECT_EQ(a, true_angles(3));
  EXPECT_NE(a, true_angles(4));
  EXPECT_GT(a.back(), 0.05);  // the RMS error is near sigma = 0.1 deg

  // The error belongs to the position: going back to an angle, by another path and after other
  // moves (as a resumed scan does), lands on the same true angle.
  Lt360EmulatorOptions noisy;
  noisy.sigma_deg = 0.1;
  noisy.seed = 3;
  Lt360Emulator table(noisy, std::make_shared<SteppedEmulatorClock>(100));
  SerialPort serial(table.device_path(), 9600);
  Ask(serial, "GO 50.0");
  Ask(serial, "CP");
  const double first_visit = table.TrueAngleDeg();
  for (const char* detour : {"GO 120.0", "GO 50.0", "GO 300.0", "GO 50.0"}) Ask(serial, detour);
  Ask(serial, "CP");
  EXPECT_EQ(table.TrueAngleDeg(), first_visit);
  EXPECT_EQ(first_visit, a[9]);  // the 10th angle of the sequence above is 50 deg too
  EXPECT_LT(a.back(), 0.15);
}

TEST(Lt360Emulator, RejectsBadOptions) {
  Lt360EmulatorOptions options;
  options.speed_deg_s = 0;
  EXPECT_THROW(Lt360Emulator{options}, std::invalid_argument);
  options = {};
  options.sigma_deg = -1;
  EXPECT_THROW(Lt360Emulator{options}, std::invalid_argument);
  options = {};
  options.accel_deg_s2 = -1;
  EXPECT_THROW(Lt360Emulator{options}, std::invalid_argument);
  options = {};
  options.table.get_position = "";
  EXPECT_THROW(Lt360Emulator{options}, std::invalid_argument);
}

}  // namespace
}  // namespace avc::sim
