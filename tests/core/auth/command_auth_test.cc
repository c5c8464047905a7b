// Motion-command keys and signatures (core/auth): key files are only used when private and well
// formed and are never overwritten; a signature verifies only for the same key, channel, cell,
// sender and contents; counters must rise and stay near the verifier's clock.

#include "core/auth/command_auth.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <avc/robot_command_t.hpp>
#include <avc/turntable_command_t.hpp>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "core/auth/command_key.h"
#include "tests/support/test_support.h"

namespace avc::auth {
namespace {

namespace fs = std::filesystem;

constexpr int64_t kNow = 1'800'000'000'000'000;  // µs since the epoch
constexpr char kChannel[] = "cell7/ROBOT_COMMAND";

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

CommandKey KeyOf(uint8_t seed) {
  CommandKey key;
  for (size_t i = 0; i < key.bytes.size(); ++i) key.bytes[i] = static_cast<uint8_t>(seed + 3 * i);
  return key;
}

avc::robot_command_t Move(const std::string& id) {
  avc::robot_command_t command{};
  command.request_id = id;
  command.kind = avc::robot_command_t::KIND_MOVE_JOINTS;
  for (int i = 0; i < 6; ++i) command.q[i] = 0.1 * i;
  return command;
}

class SignedCommands : public ::testing::Test {
 protected:
  SignedCommands()
      : clock_(kNow),
        signer_(KeyOf(1), "avc-scan@lab", "cell7", &clock_),
        verifier_(Options(), kChannel, "cell7", &clock_) {}

  static VerifierOptions Options() {
    VerifierOptions options;
    options.key = KeyOf(1);
    return options;
  }

  avc::robot_command_t Signed(const std::string& id) {
    avc::robot_command_t command = Move(id);
    signer_.Sign(command, kChannel);
    return command;
  }

  ManualClock clock_;
  CommandSigner signer_;
  CommandVerifier verifier_;
};

TEST_F(SignedCommands, AGenuineCommandPassesOnceAndItsCopyIsAReplay) {
  const avc::robot_command_t command = Signed("m1");
  EXPECT_EQ(command.auth_size, 32);
  EXPECT_EQ(command.auth_counter, kNow);
  EXPECT_EQ(verifier_.Check(command), "");
  const std::string replay = verifier_.Check(command);
  EXPECT_TRUE(Contains(replay, "replayed command from 'avc-scan@lab'")) << replay;
  // The bus stamps time and sequence after signing: they are not covered.
  avc::robot_command_t restamped = Signed("m2");
  restamped.header.utime = 12345;
  restamped.header.seq = 99;
  EXPECT_EQ(verifier_.Check(restamped), "");
  EXPECT_EQ(verifier_.rejected(), 1);
}

TEST_F(SignedCommands, ResentCommandsAreSignedAgainWithAHigherCounter) {
  avc::robot_command_t command = Move("m1");
  signer_.Sign(command, kChannel);
  const int64_t first = command.auth_counter;
  signer_.Sign(command, kChannel);  // same clock reading: still strictly above
  EXPECT_EQ(command.auth_counter, first + 1);
  EXPECT_EQ(verifier_.Check(command), "");
}

TEST_F(SignedCommands, AnyChangeAfterSigningBreaksTheSignature) {
  avc::robot_command_t moved = Signed("m1");
  moved.q[2] += 0.5;
  EXPECT_TRUE(Contains(verifier_.Check(moved), "bad signature")) << verifier_.Check(moved);
  avc::robot_command_t renamed = Signed("m2");
  renamed.request_id = "m3";
  EXPECT_TRUE(Contains(verifier_.Check(renamed), "bad signature"));
  avc::robot_command_t other_sender = Signed("m4");
  other_sender.header.source = "intruder";  // a fresh counter namespace is not for free
  EXPECT_TRUE(Contains(verifier_.Check(other_sender), "bad signature"));
  avc::robot_command_t truncated = Signed("m5");
  truncated.auth_mac.resize(16);
  truncated.auth_size = 16;
  EXPECT_TRUE(Contains(verifier_.Check(truncated), "signature of 16 bytes"));
  // And the untouched command still passes: nothing above advanced the counter.
  EXPECT_EQ(verifier_.Check(Signed("m6")), "");
}

TEST_F(SignedCommands, AnotherKeyChannelOrCellIsRefused) {
  CommandSigner stranger(KeyOf(2), "avc-scan@lab", "cell7", &clock_);
  avc::robot_command_t forged = Move("f1");
  stranger.Sign(forged, kChannel);
  EXPECT_TRUE(Contains(verifier_.Check(forged), "bad signature"));

  avc::robot_command_t for_the_table = Move("f2");
  signer_.Sign(for_the_table, "cell7/TURNTABLE_COMMAND");
  EXPECT_TRUE(Contains(verifier_.Check(for_the_table), "bad signature"));

  CommandSigner other_cell(KeyOf(1), "avc-scan@lab", "cell8", &clock_);
  avc::robot_command_t wrong_cell = Move("f3");
  other_cell.Sign(wrong_cell, "cell8/ROBOT_COMMAND");
  const std::string why = verifier_.Check(wrong_cell);
  EXPECT_TRUE(Contains(why, "command for cell 'cell8' arrived on cell 'cell7'")) << why;
}

TEST_F(SignedCommands, CountersFarFromTheClockAreStale) {
  ManualClock old_clock(kNow - 600'000'000);  // ten minutes behind
  CommandSigner behind(KeyOf(1), "old-laptop", "cell7", &old_clock);
  avc::robot_command_t command = Move("s1");
  behind.Sign(command, kChannel);
  const std::string why = verifier_.Check(command);
  EXPECT_TRUE(Contains(why, "stale command from 'old-laptop'")) << why;
  EXPECT_TRUE(Contains(why, "-600.0 s")) << why;
  // Within the window it passes, and the window can be switched off.
  old_clock.Set(kNow - 60'000'000);
  behind.Sign(command, kChannel);
  EXPECT_EQ(verifier_.Check(command), "");
}

TEST(CommandVerifier, UnsignedCommandsNeedTheExplicitSwitchExceptStops) {
  ManualClock clock(kNow);
  VerifierOptions strict;
  strict.key = KeyOf(1);
  CommandVerifier verifier(strict, kChannel, "cell7", &clock);
  avc::robot_command_t command = Move("u1");
  command.header.cell = "cell7";
  EXPECT_TRUE(Contains(verifier.Check(command), "unsigned command"));
  EXPECT_EQ(verifier.Check(command, /*signature_optional=*/true), "");
  EXPECT_TRUE(verifier.requires_signature());

  VerifierOptions open;
  open.allow_unsigned = true;
  CommandVerifier lenient(open, kChannel, "cell7", &clock);
  EXPECT_EQ(lenient.Check(command), "");
  EXPECT_TRUE(Contains(lenient.StartupLine(), "WARNING: unsigned motion commands are accepted"));

  EXPECT_THROW({ CommandVerifier keyless(VerifierOptions{}, kChannel, "cell7"); },
               std::invalid_argument);
}

TEST(CommandVerifier, TurntableCommandsAreSignedTheSameWay) {
  ManualClock clock(kNow);
  CommandSigner signer(KeyOf(1), "avc-scan", "cell7", &clock);
  VerifierOptions options;
  options.key = KeyOf(1);
  CommandVerifier verifier(options, "cell7/TURNTABLE_COMMAND", "cell7", &clock);
  avc::turntable_command_t command{};
  command.request_id = "t1";
  command.kind = avc::turntable_command_t::KIND_GOTO;
  command.angle = 1.0;
  signer.Sign(command, "cell7/TURNTABLE_COMMAND");
  EXPECT_EQ(verifier.Check(command), "");
  command.angle = 3.0;
  signer.Sign(command, "cell7/ROBOT_COMMAND");  // signed for the other device
  EXPECT_TRUE(Contains(verifier.Check(command), "bad signature"));
}

TEST(CommandMac, IsHmacSha256OfTheTaggedParts) {
  // Same inputs, same MAC; one bit of key, channel or contents changes it.
  const std::vector<uint8_t> bytes = {1, 2, 3};
  const Mac mac = CommandMac(KeyOf(1), kChannel, bytes);
  EXPECT_EQ(mac, CommandMac(KeyOf(1), kChannel, bytes));
  EXPECT_NE(mac, CommandMac(KeyOf(2), kChannel, bytes));
  EXPECT_NE(mac, CommandMac(KeyOf(1), "cell7/ROBOT_COMMANE", bytes));
  EXPECT_NE(mac, CommandMac(KeyOf(1), kChannel, {1, 2, 4}));
  // Channel and contents are length-prefixed: moving a byte across the boundary changes it.
  EXPECT_NE(CommandMac(KeyOf(1), "ab", {'c'}), CommandMac(KeyOf(1), "a", {'b', 'c'}));
}

TEST(CommandKeyFile, GeneratedKeysArePrivateReadableAndNeverOverwritten) {
  testing::TempDir dir("avc-key");
  const fs::path file = dir / "sub" / "cell7.key";
  const CommandKey made = GenerateCommandKey(file);
  struct stat info {};
  ASSERT_EQ(::stat(file.c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0600u);
  EXPECT_EQ(testing::ReadFile(file).size(), 65u);  // 64 hex digits and a newline
  const CommandKey loaded = LoadCommandKey(file);
  EXPECT_EQ(loaded.bytes, made.bytes);
  EXPECT_EQ(loaded.file, file);
  EXPECT_THROW(GenerateCommandKey(file), KeyError);
  EXPECT_EQ(LoadCommandKey(file).bytes, made.bytes);  // untouched
  EXPECT_NE(GenerateCommandKey(dir / "other.key").bytes, made.bytes);
  EXPECT_EQ(LoadOrGenerateCommandKey(file).bytes, made.bytes);
}

TEST(CommandKeyFile, BadKeyFilesAreRefusedWithTheReason) {
  testing::TempDir dir("avc-key-bad");
  const auto refusal = [](const fs::path& file) {
    try {
      LoadCommandKey(file);
    } catch (const KeyError& error) {
      return std::string(error.what());
    }
    return std::string("accepted");
  };
  EXPECT_TRUE(Contains(refusal(dir / "missing.key"), "cannot open the command key"));

  const fs::path shared = dir / "shared.key";
  GenerateCommandKey(shared);
  fs::permissions(shared, fs::perms::others_read, fs::perm_options::add);
  const std::string exposed = refusal(shared);
  EXPECT_TRUE(Contains(exposed, "can be read or written by others (mode 604)")) << exposed;
  EXPECT_TRUE(Contains(exposed, "chmod 600")) << exposed;

  const fs::path short_key = dir / "short.key";
  testing::WriteFile(short_key, "abcd\n");
  fs::permissions(short_key, fs::perms::owner_read | fs::perms::owner_write);
  EXPECT_TRUE(Contains(refusal(short_key), "not 64 hex digits"));
  const fs::path not_hex = dir / "nothex.key";
  testing::WriteFile(not_hex, std::string(63, 'a') + "g");
  fs::permissions(not_hex, fs::perms::owner_read | fs::perms::owner_write);
  EXPECT_TRUE(Contains(refusal(not_hex), "not 64 hex digits"));
  const fs::path upper = dir / "upper.key";
  testing::WriteFile(upper, std::string(64, 'F'));
  fs::permissions(upper, fs::perms::owner_read | fs::perms::owner_write);
  EXPECT_EQ(LoadCommandKey(upper).bytes[31], 0xff);

  fs::create_directories(dir / "folder.key");
  EXPECT_TRUE(Contains(refusal(dir / "folder.key"), "not a regular file"));
  fs::create_symlink(upper, dir / "link.key");
  EXPECT_TRUE(Contains(refusal(dir / "link.key"), "cannot open"));  // links are not followed
}

TEST(CommandKeyFile, TheDefaultPlaceFollowsTheEnvironment) {
  testing::TempDir dir("avc-key-env");
  ::setenv("AVC_KEY_DIR", dir.path().c_str(), 1);
  EXPECT_EQ(DefaultKeyFile("cell3"), dir / "cell3.key");
  EXPECT_FALSE(FindCommandKey("cell3").has_value());
  const CommandKey made = GenerateCommandKey(dir / "cell3.key");
  ASSERT_TRUE(FindCommandKey("cell3").has_value());
  EXPECT_EQ(FindCommandKey("cell3")->bytes, made.bytes);
  ::unsetenv("AVC_KEY_DIR");
  ::setenv("XDG_CONFIG_HOME", "/etc/xdg-test", 1);
  EXPECT_EQ(DefaultKeyFile("cell3"), fs::path("/etc/xdg-test/avc/keys/cell3.key"));
  ::unsetenv("XDG_CONFIG_HOME");
  const std::string home = std::getenv("HOME") ? std::getenv("HOME") : "";
  ::setenv("HOME", "/home/someone", 1);
  EXPECT_EQ(DefaultKeyFile("cell3"), fs::path("/home/someone/.config/avc/keys/cell3.key"));
  ::setenv("HOME", home.c_str(), 1);
}

}  // namespace
}  // namespace avc::auth
