// scan.json: round trip, atomic and deterministic writes, failed writes that keep the old record,
// a clear error for every malformed field, and finding the images a resume must capture again.

#include "orchestrator/scan_record.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <functional>
#include <stdexcept>

#include "core/util/sha256.h"
#include "tests/support/test_support.h"

namespace avc::orchestrator {
namespace {

namespace fs = std::filesystem;
using avc::testing::ReadFile;
using avc::testing::TempDir;
using avc::testing::WriteFile;
using Json = nlohmann::json;

// A scan dir with three captured images on disk and a record describing them.
struct ScanFixture {
  TempDir dir{"avc-scan-record"};
  ScanRecord record;

  ScanFixture() {
    fs::create_directories(dir.path() / "images");
    record.scan_id = "scan-20240501-0001";
    record.cell = "cell-a";
    record.created_utime = 1714550400000000;
    record.state = ScanState::kPaused;
    record.interrupted = ScanState::kActiveVision;
    record.detail = "paused by operator";
    record.fault = "";
    record.StartPhase(ScanState::kCheckDevices, 1714550400000100);
    record.StartPhase(ScanState::kActiveVision, 1714550400500000);
    record.EndPhase(1714550401000000);
    for (int i = 0; i < 3; ++i) {
      CaptureRecord capture;
      capture.index = i;
      capture.image_id = "view_000" + std::to_string(i);
      capture.file = "images/" + capture.image_id + ".png";
      const std::string bytes = "image bytes " + std::to_string(i);
      WriteFile(dir.path() / capture.file, bytes);
      capture.sha256 = Sha256Hex(bytes);
      capture.joints = {0.1 * i, -1.5707963267948966, 1.0 / 3.0, 2.5e-7, -3.14159, 6.0};
      capture.table_angle = 0.6283185307179586 * i;
      capture.phase = i == 0 ? "initial" : "active";
      capture.reason = i == 0 ? "ring 1" : "cluster 7 scored 0.42";
      capture.kept = i != 1;
      record.captures.push_back(capture);
    }
    record.options = Json{{"planner", {{"max_views", 40}, {"radius_m", 0.45}}}, {"sim", true}};
  }

  fs::path json() const { return dir.path() / "scan.json"; }
};

// Saves fixture.record, edits the saved JSON with edit, and returns LoadScanRecord's error.
std::string LoadError(const std::function<void(Json&)>& edit) {
  ScanFixture fixture;
  SaveScanRecord(fixture.record, fixture.dir.path());
  Json doc = Json::parse(ReadFile(fixture.json()));
  edit(doc);
  WriteFile(fixture.json(), doc.dump(2));
  try {
    LoadScanRecord(fixture.dir.path());
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "(loaded without error)";
}

void ExpectLoadError(const std::function<void(Json&)>& edit, const std::string& expected) {
  const std::string error = LoadError(edit);
  EXPECT_NE(error.find("scan.json: "), std::string::npos) << error;
  EXPECT_NE(error.find(expected), std::string::npos)
      << "expected '" << expected << "' in: " << error;
}

TEST(ScanRecord, RoundTripsEveryField) {
  ScanFixture fixture;
  SaveScanRecord(fixture.record, fixture.dir.path());
  const ScanRecord loaded = LoadScanRecord(fixture.dir.path());
  const ScanRecord& saved = fixture.record;
  EXPECT_EQ(loaded.scan_id, saved.scan_id);
  EXPECT_EQ(loaded.cell, saved.cell);
  EXPECT_EQ(loaded.created_utime, saved.created_utime);
  EXPECT_EQ(loaded.state, ScanState::kPaused);
  ASSERT_TRUE(loaded.interrupted.has_value());
  EXPECT_EQ(*loaded.interrupted, ScanState::kActiveVision);
  EXPECT_EQ(loaded.detail, saved.detail);
  EXPECT_EQ(loaded.fault, saved.fault);
  ASSERT_EQ(loaded.phases.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(loaded.phases[i].state, saved.phases[i].state);
    EXPECT_EQ(loaded.phases[i].start_utime, saved.phases[i].start_utime);
    EXPECT_EQ(loaded.phases[i].end_utime, saved.phases[i].end_utime);
  }
  ASSERT_EQ(loaded.captures.size(), saved.captures.size());
  for (size_t i = 0; i < saved.captures.size(); ++i) {
    const CaptureRecord& a = loaded.captures[i];
    const CaptureRecord& b = saved.captures[i];
    EXPECT_EQ(a.index, b.index);
    EXPECT_EQ(a.image_id, b.image_id);
    EXPECT_EQ(a.file, b.file);
    EXPECT_EQ(a.sha256, b.sha256);
    for (size_t j = 0; j < 6; ++j) EXPECT_EQ(a.joints[j], b.joints[j]) << "bit-exact doubles";
    EXPECT_EQ(a.table_angle, b.table_angle);
    EXPECT_EQ(a.phase, b.phase);
    EXPECT_EQ(a.reason, b.reason);
    EXPECT_EQ(a.kept, b.kept);
  }
  EXPECT_EQ(loaded.options, saved.options);
  EXPECT_TRUE(loaded == saved);
}

TEST(ScanRecord, PhasesOpenAndClose) {
  ScanFixture fixture;
  const std::vector<PhaseTiming> expected = {{"CHECK_DEVICES", 1714550400000100, 1714550400500000},
                                             {"ACTIVE_VISION", 1714550400500000, 1714550401000000}};
  EXPECT_EQ(fixture.record.phases, expected);
  fixture.record.EndPhase(1714550402000000);  // nothing running: no change
  EXPECT_EQ(fixture.record.phases, expected);
  fixture.record.StartPhase(ScanState::kBuild, 1714550403000000);
  EXPECT_EQ(fixture.record.phases.back().end_utime, 0);
}

TEST(ScanRecord, CaptureForFindsByIndex) {
  ScanFixture fixture;
  ASSERT_NE(fixture.record.CaptureFor(2), nullptr);
  EXPECT_EQ(fixture.record.CaptureFor(2)->image_id, "view_0002");
  EXPECT_EQ(fixture.record.CaptureFor(7), nullptr);
}

TEST(ScanRecord, SavingIsDeterministicAndLeavesNoTempFile) {
  ScanFixture fixture;
  SaveScanRecord(fixture.record, fixture.dir.path());
  const std::string first = ReadFile(fixture.json());
  SaveScanRecord(LoadScanRecord(fixture.dir.path()), fixture.dir.path());
  EXPECT_EQ(ReadFile(fixture.json()), first);
  EXPECT_FALSE(fs::exists(fixture.dir.path() / "scan.json.tmp"));

  // Fixed key order, 2-space indent, trailing newline.
  EXPECT_EQ(first.rfind("{\n  \"format_version\": 1,\n  \"scan_id\": ", 0), 0u) << first;
  EXPECT_EQ(first.back(), '\n');
  const std::vector<std::string> order = {"\"format_version\"", "\"scan_id\"", "\"cell\"",
                                          "\"created_utime\"",  "\"state\"",   "\"interrupted\"",
                                          "\"detail\"",         "\"fault\"",   "\"phases\"",
                                          "\"captures\"",       "\"options\""};
  size_t previous = 0;
  for (const std::string& key : order) {
    const size_t at = first.find(key);
    ASSERT_NE(at, std::string::npos) << key;
    EXPECT_GT(at, previous) << key;
    previous = at;
  }
}

TEST(ScanRecord, SaveIntoAMissingDirectoryNamesThePath) {
  ScanFixture fixture;
  const fs::path missing = fixture.dir.path() / "no" / "such";
  try {
    SaveScanRecord(fixture.record, missing);
    FAIL() << "saved into a missing directory";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find((missing / "scan.json.tmp").string()), std::string::npos) << what;
    EXPECT_NE(what.find("No such file or directory"), std::string::npos) << what;
  }
}

TEST(ScanRecord, FailedSaveKeepsThePreviousRecord) {
  ScanFixture fixture;
  SaveScanRecord(fixture.record, fixture.dir.path());
  const std::string before = ReadFile(fixture.json());
  // A directory where the temp file goes: creating it fails (EISDIR) even for root.
  fs::create_directory(fixture.dir.path() / "scan.json.tmp");
  fixture.record.state = ScanState::kActiveVision;
  fixture.record.interrupted.reset();
  try {
    SaveScanRecord(fixture.record, fixture.dir.path());
    FAIL() << "saved over a directory";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("scan.json.tmp"), std::string::npos) << e.what();
  }
  EXPECT_EQ(ReadFile(fixture.json()), before);
}

// A write that fails half way (as on a full disk): here the file size limit makes write() fail
// with EFBIG. Run in a child so the limit cannot touch the test's own output.
TEST(ScanRecord, WriteErrorHalfWayKeepsThePreviousRecordAndRemovesTheTempFile) {
  ScanFixture fixture;
  SaveScanRecord(fixture.record, fixture.dir.path());
  const std::string before = ReadFile(fixture.json());
  fixture.record.options["padding"] = std::string(64 * 1024, 'x');

  int pipe_fds[2];
  ASSERT_EQ(pipe(pipe_fds), 0);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    close(pipe_fds[0]);
    signal(SIGXFSZ, SIG_IGN);
    const rlimit limit = {4096, 4096};
    setrlimit(RLIMIT_FSIZE, &limit);
    std::string message = "(saved)";
    try {
      SaveScanRecord(fixture.record, fixture.dir.path());
    } catch (const std::runtime_error& e) {
      message = e.what();
    }
    const ssize_t ignored = write(pipe_fds[1], message.data(), message.size());
    (void)ignored;
    _exit(0);
  }
  close(pipe_fds[1]);
  std::string message;
  char buffer[512];
  for (ssize_t n; (n = read(pipe_fds[0], buffer, sizeof buffer)) > 0;) message.append(buffer, n);
  close(pipe_fds[0]);
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));

  EXPECT_NE(message.find("cannot write " + (fixture.dir.path() / "scan.json.tmp").string()),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("File too large"), std::string::npos) << message;
  EXPECT_EQ(ReadFile(fixture.json()), before);
  EXPECT_FALSE(fs::exists(fixture.dir.path() / "scan.json.tmp"));
}

TEST(ScanRecord, RefusesToSaveARecordItCouldNotLoad) {
  ScanFixture fixture;
  fixture.record.captures[1].joints[3] = std::nan("");
  EXPECT_THROW(SaveScanRecord(fixture.record, fixture.dir.path()), std::invalid_argument);
  EXPECT_FALSE(fs::exists(fixture.json()));
}

TEST(ScanRecord, MissingFile) {
  TempDir dir("avc-scan-record");
  try {
    LoadScanRecord(dir.path());
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find((dir.path() / "scan.json").string()), std::string::npos);
  }
}

TEST(ScanRecord, UnparsableJsonGivesTheBytePosition) {
  ScanFixture fixture;
  WriteFile(fixture.json(), "{\"format_version\": 1,, }");
  try {
    LoadScanRecord(fixture.dir.path());
    FAIL();
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(fixture.json().string() + ": not valid JSON at byte 22"), std::string::npos)
        << what;
  }
}

TEST(ScanRecord, MalformedFieldsAreNamed) {
  ExpectLoadError([](Json& d) { d["format_version"] = 2; },
                  "format_version 2 is not supported (this build reads 1)");
  ExpectLoadError([](Json& d) { d["format_version"] = "1"; }, "format_version must be an integer");
  ExpectLoadError([](Json& d) { d.erase("format_version"); }, "format_version is missing");
  ExpectLoadError([](Json& d) { d["state"] = "SCANNING"; }, "state 'SCANNING' is not a scan state");
  ExpectLoadError([](Json& d) { d["interrupted"] = "DONE"; },
                  "interrupted must be a working state, not DONE");
  ExpectLoadError([](Json& d) { d["interrupted"] = nullptr; }, "interrupted must name");
  ExpectLoadError([](Json& d) { d["scan_id"] = 7; }, "scan_id must be a string");
  ExpectLoadError([](Json& d) { d["created_utime"] = 1.5; }, "created_utime must be an integer");
  ExpectLoadError([](Json& d) { d["phases"] = Json::object(); }, "phases must be a list");
  ExpectLoadError([](Json& d) { d["phases"][1]["state"] = "NAP"; },
                  "phases[1].state 'NAP' is not a scan state");
  ExpectLoadError(
      [](Json& d) {
        d["captures"][2]["joints"] = {1, 2, 3};
      },
      "captures[2].joints must be 6 numbers");
  ExpectLoadError([](Json& d) { d["captures"][2]["joints"][4] = "a"; },
                  "captures[2].joints[4] must be a number");
  ExpectLoadError([](Json& d) { d["captures"][0]["kept"] = 1; },
                  "captures[0].kept must be true or false");
  ExpectLoadError([](Json& d) { d["captures"][1].erase("sha256"); },
                  "captures[1].sha256 is missing");
  ExpectLoadError([](Json& d) { d["captures"][1]["sha256"] = "abc"; },
                  "captures[1].sha256 must be 64 lower-case hex digits");
  ExpectLoadError([](Json& d) { d["captures"][1]["phase"] = "later"; },
                  "captures[1].phase 'later' must be empty, frame, initial or active");
  ExpectLoadError([](Json& d) { d["captures"][1]["index"] = -1; },
                  "captures[1].index is out of range");
  ExpectLoadError([](Json& d) { d["captures"][2]["index"] = 0; },
                  "captures[2].index 0 is used by an earlier capture");
  ExpectLoadError([](Json& d) { d["captures"][2]["image_id"] = "view_0001"; },
                  "captures[2].image_id 'view_0001' is used by an earlier capture");
  ExpectLoadError([](Json& d) { d["captures"][1]["file"] = "/etc/passwd"; },
                  "captures[1].file '/etc/passwd' must be relative to the scan directory");
  ExpectLoadError([](Json& d) { d["captures"][1]["file"] = "images/../../x.png"; },
                  "captures[1].file 'images/../../x.png' must stay inside the scan directory");
  ExpectLoadError([](Json& d) { d.erase("options"); }, "options is missing");
}

TEST(ScanRecord, NumbersTooLargeForADoubleAreRefused) {
  // JSON has no NaN or infinity literals; an overflowing number is the way to smuggle one in.
  ScanFixture fixture;
  SaveScanRecord(fixture.record, fixture.dir.path());
  std::string text = ReadFile(fixture.json());
  const std::string angle = "\"table_angle\": 0.0";
  const size_t at = text.find(angle);
  ASSERT_NE(at, std::string::npos) << text;
  text.replace(at, angle.size(), "\"table_angle\": 1e999");
  WriteFile(fixture.json(), text);
  try {
    LoadScanRecord(fixture.dir.path());
    FAIL();
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(fixture.json().string() + ": not valid JSON"), std::string::npos) << what;
    EXPECT_NE(what.find("1e999"), std::string::npos) << what;
  }
}

TEST(ScanRecord, VerifyCapturesFindsMissingAndChangedImages) {
  ScanFixture fixture;
  EXPECT_TRUE(VerifyCaptures(fixture.record, fixture.dir.path()).empty());

  fs::remove(fixture.dir.path() / "images/view_0001.png");
  WriteFile(fixture.dir.path() / "images/view_0002.png", "retouched");
  const std::vector<std::string> problems = VerifyCaptures(fixture.record, fixture.dir.path());
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems[0], "view_0001: images/view_0001.png is missing");
  EXPECT_EQ(problems[1].rfind("view_0002: images/view_0002.png has changed since capture (sha256 " +
                                  Sha256Hex(std::string("retouched")),
                              0),
            0u)
      << problems[1];
}

}  // namespace
}  // namespace avc::orchestrator
