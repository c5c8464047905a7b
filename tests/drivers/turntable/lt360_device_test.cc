// The real serial backend (SerialPort + Lt360Device + TurntableController) against the LT360
// emulator on a real pseudo-terminal. The emulator's clock advances 0.5 s per command, so moves
// of many emulated seconds take a few milliseconds; the controller's clock is a ManualClock the
// test advances per poll.

#include "drivers/turntable/lt360_device.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "core/util/clock.h"
#include "drivers/turntable/turntable_controller.h"
#include "sim/emulators/lt360/lt360_emulator.h"

namespace avc::turntable {
namespace {

using sim::Lt360Emulator;
using sim::Lt360EmulatorOptions;
using sim::Lt360Fault;
using std::chrono::milliseconds;

constexpr milliseconds kTestCommandTimeout{300};

struct Rig {
  explicit Rig(Lt360EmulatorOptions emulator_options = {}, DeviceOptions device_options = {})
      : emulator_clock(std::make_shared<sim::SteppedEmulatorClock>(0.5)),
        emulator(std::move(emulator_options), emulator_clock),
        device(std::make_unique<SerialPort>(emulator.device_path(), 9600),
               WithTestTimeout(std::move(device_options))) {}

  static DeviceOptions WithTestTimeout(DeviceOptions options) {
    options.command_timeout = kTestCommandTimeout;
    return options;
  }

  // Polls until the move ends; the controller clock advances 0.5 s per poll.
  MoveReport RunMove(TurntableController& controller, int max_polls = 200) {
    for (int i = 0; i < max_polls; ++i) {
      controller_clock.Advance(500'000);
      MoveReport report = controller.Poll();
      if (report.result != MoveResult::kRunning) return report;
    }
    return {MoveResult::kRunning, "still running after max_polls"};
  }

  std::shared_ptr<sim::SteppedEmulatorClock> emulator_clock;
  Lt360Emulator emulator;
  Lt360Device device;
  ManualClock controller_clock{0};
};

TEST(Lt360Device, ReadsPositionAndMotion) {
  Lt360EmulatorOptions options;
  options.start_deg = 42.3;
  Rig rig(options);
  EXPECT_EQ(rig.device.PositionTenths(), 423);
  EXPECT_EQ(rig.device.Moving(), Motion::kNone);
  EXPECT_EQ(rig.device.stats().commands, 2);
}

TEST(Lt360Device, GotoArrivesWithinATenthOfTheTarget) {
  Lt360EmulatorOptions options;
  options.sigma_deg = 0.05;
  options.seed = 7;
  Rig rig(options);
  TurntableController controller(rig.device, {}, rig.controller_clock);
  controller.StartGoto(1234, Direction::kShortest, 0);
  ASSERT_TRUE(controller.move_active());
  EXPECT_EQ(controller.target_tenths(), 1234);
  const MoveReport report = rig.RunMove(controller);
  ASSERT_EQ(report.result, MoveResult::kDone) << report.detail;
  EXPECT_LE(std::abs(controller.last_reading().position_tenths - 1234), 1);
  EXPECT_EQ(rig.emulator.ReportedTenths(), 1234);
  EXPECT_FALSE(rig.emulator.moving());
  // The true angle carries the emulator's per-move error: near, not equal, to what is reported.
  EXPECT_NEAR(rig.emulator.TrueAngleDeg(), 123.4, 0.3);
  EXPECT_NE(rig.emulator.TrueAngleDeg(), 123.4);
}

TEST(Lt360Device, GotoHonoursTheRequestedDirection) {
  Lt360EmulatorOptions options;
  options.start_deg = 10;
  Rig rig(options);
  TurntableController controller(rig.device, {}, rig.controller_clock);
  // 10 -> 350 CCW is the long way round (340 deg), passing 180.
  controller.StartGoto(3500, Direction::kCcw, 0);
  bool passed_half_turn = false;
  MoveReport report;
  for (int i = 0; i < 100 && report.result == MoveResult::kRunning; ++i) {
    rig.controller_clock.Advance(500'000);
    report = controller.Poll();
    const int at = controller.last_reading().position_tenths;
    if (report.result == MoveResult::kRunning) {
      EXPECT_EQ(controller.last_reading().motion, Motion::kCcw);
      passed_half_turn |= at > 1000 && at < 3000;
    }
  }
  ASSERT_EQ(report.result, MoveResult::kDone) << report.detail;
  EXPECT_TRUE(passed_half_turn);
  EXPECT_EQ(rig.emulator.ReportedTenths(), 3500);

  // 350 -> 340 CW is the short way.
  controller.StartGoto(3400, Direction::kCw, 0);
  rig.controller_clock.Advance(100'000);
  report = rig.RunMove(controller);
  ASSERT_EQ(report.result, MoveResult::kDone) << report.detail;
  EXPECT_EQ(rig.emulator.ReportedTenths(), 3400);
}

TEST(Lt360Device, StepsAndHomes) {
  Rig rig;
  TurntableController controller(rig.device, {}, rig.controller_clock);
  controller.StartStep(-455, 60);
  EXPECT_DOUBLE_EQ(rig.emulator.speed_deg_s(), 60);  // the speed command went out first
  MoveReport report = rig.RunMove(controller);
  ASSERT_EQ(report.result, MoveResult::kDone) << report.detail;
  EXPECT_EQ(rig.emulator.ReportedTenths(), 3145);
  EXPECT_FALSE(controller.homed());
  controller.StartHome(0);
  report = rig.RunMove(controller);
  ASSERT_EQ(report.result, MoveResult::kDone) << report.detail;
  EXPECT_EQ(rig.emulator.ReportedTenths(), 0);
  EXPECT_TRUE(controller.homed());
  EXPECT_EQ(rig.emulator.moves_started(), 2);
}

TEST(Lt360Device, TimeoutGivesAClearErrorAndTheDriverRecovers) {
  Rig rig;
  rig.emulator.InjectFault(Lt360Fault::kNoReply);
  try {
    rig.device.PositionTenths();
    FAIL() << "no timeout";
  } catch (const SerialTimeout& e) {
    EXPECT_EQ(std::string(e.what()), "serial timeout after 0.3 s waiting for reply to 'CP' on " +
                                         rig.emulator.device_path());
  }
  EXPECT_EQ(rig.device.stats().timeouts, 1);
  EXPECT_EQ(rig.device.PositionTenths(), 0);
}

TEST(Lt360Device, DroppedTerminatorTimesOutThenStaleBytesAreFlushed) {
  Lt360EmulatorOptions options;
  options.start_deg = 200.5;
  Rig rig(options);
  rig.emulator.InjectFault(Lt360Fault::kDropTerminator);
  EXPECT_THROW(rig.device.PositionTenths(), SerialTimeout);
  // Without the flush, "+200.5" left over would be glued to the next reply.
  EXPECT_EQ(rig.device.Recover(), 2005);
  EXPECT_EQ(rig.device.stats().invalid_replies, 0);
}

TEST(Lt360Device, GarbledReplyIsRetried) {
  Lt360EmulatorOptions options;
  options.start_deg = 90;
  Rig rig(options);
  rig.emulator.InjectFault(Lt360Fault::kGarbledReply, 1);
  EXPECT_EQ(rig.device.PositionTenths(), 900);
  EXPECT_EQ(rig.device.stats().invalid_replies, 1);
  EXPECT_EQ(rig.device.stats().commands, 2);

  // More garbage than retries: the error says what came back and how often it was tried.
  rig.emulator.InjectFault(Lt360Fault::kGarbledReply, 3);
  try {
    rig.device.Moving();
    FAIL() << "garbage accepted";
  } catch (const InvalidReply& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("invalid moving reply"), std::string::npos) << what;
    EXPECT_NE(what.find("after 3 attempts"), std::string::npos) << what;
    EXPECT_NE(what.find(rig.emulator.device_path()), std::string::npos) << what;
  }
}

TEST(Lt360Device, RelativeStepIsNeverRepeated) {
  Rig rig;
  rig.emulator.InjectFault(Lt360Fault::kGarbledReply, 1);
  EXPECT_THROW(rig.device.Step(100), InvalidReply);
  EXPECT_EQ(rig.emulator.moves_started(), 1);
}

TEST(Lt360Device, StalledTableIsReportedFailedAndStopped) {
  Rig rig;
  ControllerOptions options;
  options.stall_timeout_s = 2;
  TurntableController controller(rig.device, options, rig.controller_clock);
  controller.StartGoto(1800, Direction::kShortest, 0);
  rig.controller_clock.Advance(500'000);
  ASSERT_EQ(controller.Poll().result, MoveResult::kRunning);
  rig.emulator.InjectFault(Lt360Fault::kStall);
  const MoveReport report = rig.RunMove(controller, 20);
  ASSERT_EQ(report.result, MoveResult::kFailed);
  EXPECT_NE(report.detail.find("stalled"), std::string::npos) << report.detail;
  EXPECT_NE(report.detail.find("target 180.0 deg"), std::string::npos) << report.detail;
  EXPECT_FALSE(controller.move_active());
  EXPECT_FALSE(rig.emulator.moving());  // the controller sent stop
  EXPECT_LT(rig.emulator.ReportedTenths(), 1800);
}

TEST(Lt360Device, SlowMoveFailsOnItsDurationLimit) {
  Rig rig;
  ControllerOptions options;
  options.duration_margin = 1;
  options.duration_slack_s = 0;
  options.stall_timeout_s = 1000;
  TurntableController controller(rig.device, options, rig.controller_clock);
  controller.StartGoto(900, Direction::kShortest, 0);  // 90 deg at 30 deg/s: 3 s allowed
  rig.controller_clock.Advance(4'000'000);
  const MoveReport report = controller.Poll();
  ASSERT_EQ(report.result, MoveResult::kFailed);
  EXPECT_NE(report.detail.find("took longer than 3.0 s"), std::string::npos) << report.detail;
}

TEST(Lt360Device, RejectedCommandNamesTheCommand) {
  DeviceOptions options;
  options.table.goto_shortest = "GOTO {angle}";  // the emulator speaks "GO {angle}"
  Rig rig({}, options);
  try {
    rig.device.Goto(100, Direction::kShortest);
    FAIL() << "no error";
  } catch (const ProtocolError& e) {
    EXPECT_NE(std::string(e.what()).find("rejected 'GOTO 10.0'"), std::string::npos) << e.what();
  }
}

TEST(Lt360Device, DisconnectIsASerialError) {
  Rig rig;
  EXPECT_EQ(rig.device.PositionTenths(), 0);
  rig.emulator.Disconnect();
  EXPECT_THROW(rig.device.PositionTenths(), SerialError);
}

TEST(SerialPort, BadPathAndBaudGiveClearErrors) {
  try {
    SerialPort port("/dev/does-not-exist-lt360", 9600);
    FAIL() << "opened";
  } catch (const SerialError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot open /dev/does-not-exist-lt360"),
              std::string::npos);
  }
  sim::Lt360Emulator emulator({});
  EXPECT_THROW(SerialPort(emulator.device_path(), 12345), std::invalid_argument);
  EXPECT_THROW(SerialPort("/dev/null", 9600), SerialError);  // not a tty
}

TEST(TurntableController, AngularDistanceIsShortestSigned) {
  EXPECT_EQ(AngularDistanceTenths(100, 3500), -200);
  EXPECT_EQ(AngularDistanceTenths(3500, 100), 200);
  EXPECT_EQ(AngularDistanceTenths(0, 1800), 1800);
  EXPECT_EQ(AngularDistanceTenths(1234, 1234), 0);
  EXPECT_EQ(NormaliseTenths(-5), 3595);
  EXPECT_EQ(NormaliseTenths(7205), 5);
}

}  // namespace
}  // namespace avc::turntable
