#include "orchestrator/scan_record.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

#include "core/util/file_io.h"
#include "core/util/sha256.h"

namespace avc::orchestrator {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using OrderedJson = nlohmann::ordered_json;

constexpr const char* kFileName = "scan.json";

// ---- Writing ----------------------------------------------------------------------------------

OrderedJson CaptureToJson(const CaptureRecord& capture) {
  return {{"index", capture.index},
          {"image_id", capture.image_id},
          {"file", capture.file},
          {"sha256", capture.sha256},
          {"joints", capture.joints},
          {"table_angle", capture.table_angle},
          {"reported_T_base_flange", capture.reported_T_base_flange},
          {"reported_table_angle", capture.reported_table_angle},
          {"phase", capture.phase},
          {"reason", capture.reason},
          {"kept", capture.kept}};
}

OrderedJson RecordToJson(const ScanRecord& record) {
  OrderedJson phases = OrderedJson::array();
  for (const PhaseTiming& phase : record.phases) {
    phases.push_back({{"state", phase.state},
                      {"start_utime", phase.start_utime},
                      {"end_utime", phase.end_utime}});
  }
  OrderedJson captures = OrderedJson::array();
  for (const CaptureRecord& capture : record.captures) captures.push_back(CaptureToJson(capture));
  OrderedJson doc;
  doc["format_version"] = ScanRecord::kFormatVersion;
  doc["scan_id"] = record.scan_id;
  doc["cell"] = record.cell;
  doc["created_utime"] = record.created_utime;
  doc["state"] = StateName(record.state);
  doc["interrupted"] =
      record.interrupted ? OrderedJson(StateName(*record.interrupted)) : OrderedJson(nullptr);
  doc["detail"] = record.detail;
  doc["fault"] = record.fault;
  doc["phases"] = std::move(phases);
  doc["captures"] = std::move(captures);
  // Json keeps object keys sorted, so the options come out in a fixed order too.
  doc["options"] = OrderedJson::parse(record.options.dump());
  return doc;
}

// ---- Checks shared by saving and loading ------------------------------------------------------

bool IsHex64(const std::string& text) {
  if (text.size() != 64) return false;
  for (char c : text) {
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  }
  return true;
}

// Why file cannot name a file inside the scan dir, or "".
std::string PathProblem(const std::string& file) {
  if (file.empty()) return "is empty";
  const fs::path path(file);
  if (path.has_root_path()) return fmt::format("'{}' must be relative to the scan directory", file);
  for (const fs::path& part : path) {
    if (part == "..")
      return fmt::format("'{}' must stay inside the scan directory (no '..')", file);
  }
  return "";
}

// The first problem of a record whose fields all have the right types, as "field problem", or "".
std::string CheckRecord(const ScanRecord& record) {
  const bool interruption = record.state == ScanState::kPaused || record.state == ScanState::kFault;
  if (interruption && !record.interrupted) {
    return fmt::format("interrupted must name the working state {} interrupted",
                       StateName(record.state));
  }
  if (!interruption && record.interrupted) {
    return fmt::format("interrupted must be null in state {}", StateName(record.state));
  }
  if (record.interrupted && !IsWorkingState(*record.interrupted)) {
    return fmt::format("interrupted must be a working state, not {}",
                       StateName(*record.interrupted));
  }
  for (size_t i = 0; i < record.phases.size(); ++i) {
    const PhaseTiming& phase = record.phases[i];
    if (!ParseScanState(phase.state)) {
      return fmt::format("phases[{}].state '{}' is not a scan state", i, phase.state);
    }
    if (phase.end_utime != 0 && phase.end_utime < phase.start_utime) {
      return fmt::format("phases[{}].end_utime is before its start_utime", i);
    }
  }
  std::set<int> indices;
  std::set<std::string> image_ids;
  for (size_t i = 0; i < record.captures.size(); ++i) {
    const CaptureRecord& capture = record.captures[i];
    const std::string field = fmt::format("captures[{}]", i);
    if (capture.index < 0) return field + ".index must not be negative";
    if (!indices.insert(capture.index).second) {
      return fmt::format("{}.index {} is used by an earlier capture", field, capture.index);
    }
    if (capture.image_id.empty()) return field + ".image_id is empty";
    if (!image_ids.insert(capture.image_id).second) {
      return fmt::format("{}.image_id '{}' is used by an earlier capture", field, capture.image_id);
    }
    if (const std::string problem = PathProblem(capture.file); !problem.empty()) {
      return field + ".file " + problem;
    }
    if (!IsHex64(capture.sha256)) return field + ".sha256 must be 64 lower-case hex digits";
    for (double joint : capture.joints) {
      if (!std::isfinite(joint)) return field + ".joints must be finite";
    }
    if (!std::isfinite(capture.table_angle)) return field + ".table_angle must be finite";
    for (double value : capture.reported_T_base_flange) {
      if (!std::isfinite(value)) return field + ".reported_T_base_flange must be finite";
    }
    if (!std::isfinite(capture.reported_table_angle)) {
      return field + ".reported_table_angle must be finite";
    }
    // Empty until the planner has finished and said which images were frames, orbit or active.
    if (!capture.phase.empty() && capture.phase != "frame" && capture.phase != "initial" &&
        capture.phase != "active") {
      return fmt::format("{}.phase '{}' must be empty, frame, initial or active", field,
                         capture.phase);
    }
  }
  return "";
}

// ---- Reading ----------------------------------------------------------------------------------

// Typed access to one JSON document; every error names the file and the field.
class Reader {
 public:
  explicit Reader(fs::path file) : file_(std::move(file)) {}

  [[noreturn]] void Fail(const std::string& field, const std::string& what) const {
    throw std::runtime_error(fmt::format("{}: {} {}", file_.string(), field, what));
  }

  const Json& At(const Json& object, const std::string& field, const char* key) const {
    const auto it = object.find(key);
    if (it == object.end()) Fail(field, "is missing");
    return *it;
  }

  std::string String(const Json& object, const std::string& where, const char* key) const {
    const std::string field = Field(where, key);
    const Json& value = At(object, field, key);
    if (!value.is_string()) Fail(field, "must be a string");
    return value.get<std::string>();
  }

  int64_t Integer(const Json& object, const std::string& where, const char* key) const {
    const std::string field = Field(where, key);
    return Integer(At(object, field, key), field);
  }

  int64_t Integer(const Json& value, const std::string& field) const {
    if (!value.is_number_integer()) Fail(field, "must be an integer");
    if (value.is_number_unsigned() &&
        value.get<uint64_t>() > static_cast<uint64_t>(std::numeric_limits<int64_t>::max())) {
      Fail(field, "is out of range");
    }
    return value.get<int64_t>();
  }

  double Number(const Json& value, const std::string& field) const {
    if (!value.is_number()) Fail(field, "must be a number");
    const double number = value.get<double>();
    if (!std::isfinite(number)) Fail(field, "must be finite");
    return number;
  }

  bool Bool(const Json& object, const std::string& where, const char* key) const {
    const std::string field = Field(where, key);
    const Json& value = At(object, field, key);
    if (!value.is_boolean()) Fail(field, "must be true or false");
    return value.get<bool>();
  }

  ScanState State(const Json& value, const std::string& field) const {
    if (!value.is_string()) Fail(field, "must be a state name");
    const std::optional<ScanState> state = ParseScanState(value.get<std::string>());
    if (!state) Fail(field, fmt::format("'{}' is not a scan state", value.get<std::string>()));
    return *state;
  }

  const Json& Array(const Json& object, const std::string& where, const char* key) const {
    const std::string field = Field(where, key);
    const Json& value = At(object, field, key);
    if (!value.is_array()) Fail(field, "must be a list");
    return value;
  }

  static std::string Field(const std::string& where, const char* key) {
    return where.empty() ? std::string(key) : where + "." + key;
  }

 private:
  fs::path file_;
};

int IntIndex(const Reader& reader, const Json& object, const std::string& where) {
  const int64_t index = reader.Integer(object, where, "index");
  if (index < 0 || index > std::numeric_limits<int>::max()) {
    reader.Fail(where + ".index", "is out of range");
  }
  return static_cast<int>(index);
}

CaptureRecord CaptureFromJson(const Reader& reader, const Json& entry, const std::string& where) {
  if (!entry.is_object()) reader.Fail(where, "must be an object");
  CaptureRecord capture;
  capture.index = IntIndex(reader, entry, where);
  capture.image_id = reader.String(entry, where, "image_id");
  capture.file = reader.String(entry, where, "file");
  capture.sha256 = reader.String(entry, where, "sha256");
  const std::string joints_field = where + ".joints";
  const Json& joints = reader.At(entry, joints_field, "joints");
  if (!joints.is_array() || joints.size() != 6) reader.Fail(joints_field, "must be 6 numbers");
  for (size_t j = 0; j < 6; ++j) {
    capture.joints[j] = reader.Number(joints[j], fmt::format("{}[{}]", joints_field, j));
  }
  const std::string angle_field = where + ".table_angle";
  capture.table_angle = reader.Number(reader.At(entry, angle_field, "table_angle"), angle_field);
  const std::string flange_field = where + ".reported_T_base_flange";
  const Json& flange = reader.At(entry, flange_field, "reported_T_base_flange");
  if (!flange.is_array() || flange.size() != 16) reader.Fail(flange_field, "must be 16 numbers");
  for (size_t k = 0; k < 16; ++k) {
    capture.reported_T_base_flange[k] =
        reader.Number(flange[k], fmt::format("{}[{}]", flange_field, k));
  }
  const std::string reported_angle_field = where + ".reported_table_angle";
  capture.reported_table_angle = reader.Number(
      reader.At(entry, reported_angle_field, "reported_table_angle"), reported_angle_field);
  capture.phase = reader.String(entry, where, "phase");
  capture.reason = reader.String(entry, where, "reason");
  capture.kept = reader.Bool(entry, where, "kept");
  return capture;
}

ScanRecord RecordFromJson(const Reader& reader, const Json& doc) {
  if (!doc.is_object()) reader.Fail("the document", "must be a JSON object");
  const int64_t version = reader.Integer(doc, "", "format_version");
  if (version != ScanRecord::kFormatVersion) {
    reader.Fail("format_version", fmt::format("{} is not supported (this build reads {})", version,
                                              ScanRecord::kFormatVersion));
  }
  ScanRecord record;
  record.scan_id = reader.String(doc, "", "scan_id");
  record.cell = reader.String(doc, "", "cell");
  record.created_utime = reader.Integer(doc, "", "created_utime");
  record.state = reader.State(reader.At(doc, "state", "state"), "state");
  if (const auto it = doc.find("interrupted"); it != doc.end() && !it->is_null()) {
    record.interrupted = reader.State(*it, "interrupted");
  }
  record.detail = reader.String(doc, "", "detail");
  record.fault = reader.String(doc, "", "fault");
  const Json& phases = reader.Array(doc, "", "phases");
  for (size_t i = 0; i < phases.size(); ++i) {
    const std::string where = fmt::format("phases[{}]", i);
    if (!phases[i].is_object()) reader.Fail(where, "must be an object");
    PhaseTiming phase;
    phase.state = reader.String(phases[i], where, "state");
    phase.start_utime = reader.Integer(phases[i], where, "start_utime");
    phase.end_utime = reader.Integer(phases[i], where, "end_utime");
    record.phases.push_back(std::move(phase));
  }
  const Json& captures = reader.Array(doc, "", "captures");
  for (size_t i = 0; i < captures.size(); ++i) {
    record.captures.push_back(CaptureFromJson(reader, captures[i], fmt::format("captures[{}]", i)));
  }
  record.options = reader.At(doc, "options", "options");
  return record;
}

}  // namespace

const CaptureRecord* ScanRecord::CaptureFor(int index) const {
  for (const CaptureRecord& capture : captures) {
    if (capture.index == index) return &capture;
  }
  return nullptr;
}

void ScanRecord::StartPhase(ScanState phase_state, int64_t utime) {
  EndPhase(utime);
  phases.push_back({std::string(StateName(phase_state)), utime, 0});
}

void ScanRecord::EndPhase(int64_t utime) {
  if (!phases.empty() && phases.back().end_utime == 0) phases.back().end_utime = utime;
}

void SaveScanRecord(const ScanRecord& record, const fs::path& scan_dir) {
  const fs::path path = scan_dir / kFileName;
  if (const std::string problem = CheckRecord(record); !problem.empty()) {
    throw std::invalid_argument(fmt::format("refusing to write {}: {}", path.string(), problem));
  }
  WriteFileAtomically(path, RecordToJson(record).dump(2) + "\n");
}

ScanRecord LoadScanRecord(const fs::path& scan_dir) {
  const fs::path path = scan_dir / kFileName;
  if (!fs::exists(path)) throw std::runtime_error(path.string() + ": no such file");
  const std::string bytes = ReadFile(path);
  Json doc;
  try {
    doc = Json::parse(bytes);
  } catch (const Json::parse_error& e) {
    throw std::runtime_error(
        fmt::format("{}: not valid JSON at byte {}: {}", path.string(), e.byte, e.what()));
  } catch (const Json::exception& e) {
    // A number too large for a double ("1e999") is refused here, not turned into infinity.
    throw std::runtime_error(fmt::format("{}: not valid JSON: {}", path.string(), e.what()));
  }
  const Reader reader(path);
  ScanRecord record = RecordFromJson(reader, doc);
  if (const std::string problem = CheckRecord(record); !problem.empty()) {
    throw std::runtime_error(fmt::format("{}: {}", path.string(), problem));
  }
  return record;
}

std::vector<std::string> VerifyCaptures(const ScanRecord& record, const fs::path& scan_dir) {
  std::vector<std::string> problems;
  for (const CaptureRecord& capture : record.captures) {
    const fs::path file = scan_dir / capture.file;
    if (!fs::is_regular_file(file)) {
      problems.push_back(fmt::format("{}: {} is missing", capture.image_id, capture.file));
      continue;
    }
    const std::string sha256 = Sha256Hex(ReadFile(file));
    if (sha256 != capture.sha256) {
      problems.push_back(fmt::format("{}: {} has changed since capture (sha256 {}, recorded {})",
                                     capture.image_id, capture.file, sha256, capture.sha256));
    }
  }
  return problems;
}

}  // namespace avc::orchestrator
