#pragma once

// The text side of the options mechanism (option_table.h), independent of any options struct:
// option values as text, "name=value" assignments, TOML files flattened to assignments, and the
// configuration in force rendered back as TOML.

#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace avc::config {

// A bad option: unknown name, malformed or out-of-range value, a file that does not parse, or
// settings the options refuse together. The message names the option and where it came from.
class ConfigError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// What one option is, for --help, the options reference and range checks.
struct OptionSpec {
  std::string unit;  // "m", "px", "deg", "s"; empty for counts, ratios and switches
  std::string doc;   // one line: what it does and what it trades off
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
};

// One setting to apply, and where it came from ("--set", "builder.toml:12").
struct Assignment {
  std::string name;
  std::string value;
  std::string where;
};

// "section.field=value" split at the first '='. Throws ConfigError naming `where` when there is
// no '=' or no name.
Assignment ParseAssignment(std::string_view text, std::string where);

// Every value of a TOML document as an assignment: nested tables give dotted names
// ([surface.fit] degree = 2 -> "surface.fit.degree"), strings their text, numbers and booleans
// their TOML spelling; `where` is "file:line". Arrays, dates and syntax errors throw ConfigError.
std::vector<Assignment> ReadTomlAssignments(std::string_view text, const std::string& file);
// A config file's assignments: YAML for a .yaml or .yml file (option_yaml.h), else TOML.
std::vector<Assignment> ReadConfigFile(const std::string& path);

// Every file's assignments in order, then `sets` ("name=value", named "--set").
std::vector<Assignment> ReadAssignments(const std::vector<std::string>& files,
                                        const std::vector<std::string>& sets);

// An optional option's text when it is unset.
inline constexpr char kNone[] = "none";

// True for text TOML reads as a number or boolean (written bare), false for text that needs
// quotes.
bool IsTomlLiteral(std::string_view text);

// Values to and from text. Every parser throws ConfigError (without a name; the table adds it).
// Numbers are checked against [spec.min, spec.max].
int64_t ParseInteger(std::string_view text, const OptionSpec& spec);
double ParseReal(std::string_view text, const OptionSpec& spec);
bool ParseSwitch(std::string_view text);
// The shortest text that reads back to the same value, always with a '.' or exponent for reals
// so TOML keeps the type.
std::string RealText(double value);

// Values by dotted name, in the order given, as a TOML document: top-level names first, then
// one [section] per prefix in order of first appearance. `quoted` marks string values.
struct NamedValue {
  std::string name;
  std::string text;
  bool quoted = false;
};
std::string RenderToml(const std::vector<NamedValue>& values);

}  // namespace avc::config
