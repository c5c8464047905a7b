#pragma once

// One options mechanism for every service: each option of an options struct is declared once in
// an OptionTable (dotted name, unit, range, one-line doc, and how to reach the field), and from
// that one declaration the service gets
//  - `--config FILE` (TOML; [section] tables, dotted names) and `--set SECTION.FIELD=VALUE`,
//    applied in that order over the defaults, with one validation contract: any bad name or
//    value throws ConfigError naming it and where it came from, before the service starts;
//  - the configuration in force as TOML text (published on CONFIG, named by every stage result,
//    kept in the scan's folder), which Load reads back to the same values;
//  - the options reference for --help.
//
//   OptionTable<SurfacerOptions> table("avc-surfacer", [](const SurfacerOptions& o) {
//     return o.Problem();  // "" when usable as a whole
//   });
//   table.Add("surface.alpha_factor", [](auto& o) -> auto& { return o.surface.alpha_factor; },
//             {"spacings", "Phase 1 alpha: larger fills more gaps and bridges more leaves", 0.5});

#include <fmt/format.h>

#include <chrono>
#include <concepts>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/config/option_text.h"

namespace avc::config {

template <typename Options>
class OptionTable {
 public:
  // "" when the options are usable together, else the problem.
  using Check = std::function<std::string(const Options&)>;

  explicit OptionTable(std::string owner, Check check = {})
      : owner_(std::move(owner)), check_(std::move(check)) {}

  // A bool, integer, real, std::string, std::chrono::milliseconds (an integer of ms) or
  // std::optional<double> ("none" when unset) field; `access` is a generic lambda returning a
  // reference to it: [](auto& o) -> auto& { return o.section.field; }.
  template <typename Access>
  OptionTable& Add(std::string name, Access access, OptionSpec spec = {}) {
    using T = std::remove_cvref_t<decltype(access(std::declval<Options&>()))>;
    Entry entry{std::move(name), spec, std::is_same_v<T, std::string>,
                [access](const Options& o) { return ValueText(access(o)); },
                [access, spec](Options& o, std::string_view text) {
                  access(o) = ParseValue<T>(text, spec);
                }};
    return Insert(std::move(entry));
  }

  // A field with a text form of its own (an enum, a list): `set` throws std::invalid_argument
  // for text it does not read.
  OptionTable& AddText(std::string name, std::function<std::string(const Options&)> get,
                       std::function<void(Options&, std::string_view)> set, OptionSpec spec) {
    return Insert(Entry{std::move(name), std::move(spec), true, std::move(get), std::move(set)});
  }

  const std::string& owner() const { return owner_; }

  // Every name, in declaration order.
  std::vector<std::string> Names() const {
    std::vector<std::string> names;
    for (const Entry& entry : entries_) names.push_back(entry.name);
    return names;
  }

  // Applies the assignments in order, then checks the whole. Throws ConfigError naming the
  // assignment and where it came from; `options` is unchanged when anything is refused.
  void Apply(Options& options, const std::vector<Assignment>& assignments) const {
    Options changed = options;
    for (const Assignment& assignment : assignments) ApplyOne(changed, assignment);
    if (check_) {
      if (const std::string problem = check_(changed); !problem.empty()) {
        throw ConfigError(fmt::format("{}: {}", owner_, problem));
      }
    }
    options = std::move(changed);
  }

  // "section.field=value" texts (a job's settings, --set), named `where` in errors.
  void ApplyTexts(Options& options, const std::vector<std::string>& texts,
                  const std::string& where) const {
    std::vector<Assignment> assignments;
    for (const std::string& text : texts) assignments.push_back(ParseAssignment(text, where));
    Apply(options, assignments);
  }

  // The defaults, then each TOML file in order, then each --set, checked as one.
  Options Load(Options defaults, const std::vector<std::string>& files,
               const std::vector<std::string>& sets) const {
    Apply(defaults, ReadAssignments(files, sets));
    return defaults;
  }

  bool Has(const std::string& name) const { return names_.contains(name); }

  // Every option's value as a TOML document that Load reads back to the same options.
  std::string ToToml(const Options& options) const {
    std::vector<NamedValue> values;
    for (const Entry& entry : entries_) {
      std::string text = entry.get(options);
      const bool quoted = entry.quoted || !IsTomlLiteral(text);
      values.push_back({entry.name, std::move(text), quoted});
    }
    return RenderToml(values);
  }

  // A Markdown table of every option (the generated options reference, OPTIONS.md).
  std::string MarkdownReference(const Options& defaults) const {
    std::string text =
        "| Option | Default | Unit | Range | What it does |\n|---|---|---|---|---|\n";
    const auto cell = [](std::string value) {
      for (size_t at = value.find('|'); at != std::string::npos; at = value.find('|', at + 2)) {
        value.insert(at, "\\");
      }
      return value;
    };
    for (const Entry& entry : entries_) {
      const std::string value = entry.get(defaults);
      text += fmt::format("| `{}` | `{}` | {} | {} | {} |\n", entry.name,
                          value.empty() ? "\"\"" : cell(value), cell(entry.spec.unit),
                          RangeText(entry.spec), cell(entry.spec.doc));
    }
    return text;
  }

  // One line per option for --help: "name = default  [unit, min..max]  doc".
  std::string Reference(const Options& defaults) const {
    std::string text;
    for (const Entry& entry : entries_) {
      text += fmt::format("  {} = {}{}\n      {}\n", entry.name, entry.get(defaults),
                          Qualifiers(entry.spec), entry.spec.doc);
    }
    return text;
  }

 private:
  struct Entry {
    std::string name;
    OptionSpec spec;
    bool quoted = false;
    std::function<std::string(const Options&)> get;
    std::function<void(Options&, std::string_view)> set;
  };

  OptionTable& Insert(Entry entry) {
    if (!names_.insert(entry.name).second) {
      throw std::logic_error(fmt::format("{}: option {} declared twice", owner_, entry.name));
    }
    entries_.push_back(std::move(entry));
    return *this;
  }

  void ApplyOne(Options& options, const Assignment& assignment) const {
    const std::string what =
        fmt::format("{}: {} {}={}", owner_, assignment.where, assignment.name, assignment.value);
    for (const Entry& entry : entries_) {
      if (entry.name != assignment.name) continue;
      try {
        entry.set(options, assignment.value);
      } catch (const std::invalid_argument& e) {
        throw ConfigError(fmt::format("{}: {}", what, e.what()));
      }
      return;
    }
    throw ConfigError(fmt::format("{}: no such option (`--help` lists them)", what));
  }

  static std::string ValueText(bool value) { return value ? "true" : "false"; }
  static std::string ValueText(std::chrono::milliseconds value) {
    return std::to_string(value.count());
  }
  static std::string ValueText(const std::optional<double>& value) {
    return value ? RealText(*value) : kNone;
  }
  static std::string ValueText(const std::string& value) { return value; }
  template <std::integral T>
  static std::string ValueText(T value) {
    return std::to_string(value);
  }
  template <std::floating_point T>
  static std::string ValueText(T value) {
    return RealText(value);
  }

  template <typename T>
  static T ParseValue(std::string_view text, const OptionSpec& spec) {
    if constexpr (std::is_same_v<T, bool>) {
      return ParseSwitch(text);
    } else if constexpr (std::is_same_v<T, std::chrono::milliseconds>) {
      return std::chrono::milliseconds(ParseInteger(text, spec));
    } else if constexpr (std::is_same_v<T, std::optional<double>>) {
      if (text == kNone) return std::optional<double>();
      return std::optional<double>(ParseReal(text, spec));
    } else if constexpr (std::is_same_v<T, std::string>) {
      return std::string(text);
    } else if constexpr (std::is_integral_v<T>) {
      OptionSpec within = spec;
      within.min = std::max<double>(spec.min, static_cast<double>(std::numeric_limits<T>::min()));
      within.max = std::min<double>(spec.max, static_cast<double>(std::numeric_limits<T>::max()));
      return static_cast<T>(ParseInteger(text, within));
    } else {
      static_assert(std::is_floating_point_v<T>, "an option is a bool, integer, real or string");
      return static_cast<T>(ParseReal(text, spec));
    }
  }

  // "min..max", "min..", "..max" or "" when unbounded.
  static std::string RangeText(const OptionSpec& spec) {
    const bool has_min = spec.min > -std::numeric_limits<double>::infinity();
    const bool has_max = spec.max < std::numeric_limits<double>::infinity();
    if (!has_min && !has_max) return "";
    return fmt::format("{}..{}", has_min ? fmt::format("{}", spec.min) : "",
                       has_max ? fmt::format("{}", spec.max) : "");
  }

  static std::string Qualifiers(const OptionSpec& spec) {
    std::vector<std::string> parts;
    if (!spec.unit.empty()) parts.push_back(spec.unit);
    if (const std::string range = RangeText(spec); !range.empty()) parts.push_back(range);
    if (parts.empty()) return "";
    std::string joined;
    for (const std::string& part : parts) joined += (joined.empty() ? "" : ", ") + part;
    return "  [" + joined + "]";
  }

  std::string owner_;
  Check check_;
  std::vector<Entry> entries_;
  std::set<std::string> names_;
};

}  // namespace avc::config
