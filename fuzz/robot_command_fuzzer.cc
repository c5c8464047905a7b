// A robot_command_t as avc-robot takes it in: decoded as the bus decodes, checked by the cell's
// command verifier (signature, counter, cell, channel), then, whatever the verdict (a forged
// command must not break the checks either), its targets checked against the safety envelope
// from a fixed arm pose, before and after its plant keep-out is read and, when valid, applied:
// everything between the bytes and a motion program. The verifier and envelope refuse with
// reasons; only a crash, a sanitizer report or a hang is a finding.

#include <avc/robot_command_t.hpp>
#include <cstdint>

#include "core/auth/command_auth.h"
#include "core/bus/decode.h"
#include "core/kinematics/dh_parameters.h"
#include "core/kinematics/row_major_pose.h"
#include "core/kinematics/safety_envelope.h"
#include "drivers/robot/plant_keep_out_command.h"

#include "fuzz/fuzz_support.h"

namespace {

constexpr char kChannel[] = "cell0/ROBOT_COMMAND";

avc::auth::CommandVerifier& Verifier() {
  static avc::auth::CommandVerifier verifier = [] {
    avc::auth::VerifierOptions options;
    options.key = avc::auth::CommandKey{};
    options.key->bytes.fill(0x5a);
    options.window = std::chrono::seconds(0);  // fuzzed counters are not this machine's time
    return avc::auth::CommandVerifier(options, kChannel, "cell0");
  }();
  return verifier;
}

void CheckMotion(const avc::kinematics::SafetyEnvelope& envelope,
                 const avc::robot_command_t& command) {
  const avc::kinematics::DhParameters dh = avc::kinematics::NominalUr5();
  avc::kinematics::JointVector current;
  current << 0.2, -1.4, 1.6, -1.8, -1.5, 0.1;
  avc::kinematics::JointVector target;
  for (int i = 0; i < 6; ++i) target[i] = command.q[i];
  avc::kinematics::CheckJointMove(envelope, dh, current, target, command.speed,
                                  command.acceleration);
  avc::kinematics::CheckLinearMove(envelope, dh, current,
                                   avc::kinematics::IsometryFromRowMajor(command.T_base_flange),
                                   command.speed, command.acceleration);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  avc::robot_command_t command;
  if (!avc::bus::DecodeMessage(data, size, &command)) return 0;  // refused as the bus refuses
  Verifier().Check(command, command.kind == avc::robot_command_t::KIND_STOP);
  avc::kinematics::SafetyEnvelope envelope;
  envelope.table_z_base_m = -0.2;
  CheckMotion(envelope, command);
  const avc::kinematics::PlantKeepOut keep_out = avc::robot::PlantKeepOutOf(command);
  if (keep_out.Validate().empty()) {
    envelope.plant_keep_out = keep_out;
    CheckMotion(envelope, command);
  }
  return 0;
}
