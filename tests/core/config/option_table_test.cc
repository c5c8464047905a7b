#include "core/config/option_table.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace avc::config {
namespace {

enum class Method { kPatch, kSweep };

struct Inner {
  double ratio = 0.5;
  bool enabled = true;
};

struct Options {
  int count = 4;
  std::string label = "plant";
  Method method = Method::kPatch;
  Inner inner;
  Inner deeper_owner;
};

OptionTable<Options> Table() {
  OptionTable<Options> table("avc-test", [](const Options& o) {
    return o.count > 10 && !o.inner.enabled ? "count above 10 needs inner.enabled" : "";
  });
  table.Add("count", [](auto& o) -> auto& { return o.count; }, {"", "how many", 1, 100})
      .Add("label", [](auto& o) -> auto& { return o.label; }, {"", "a name"})
      .AddText(
          "method", [](const Options& o) { return o.method == Method::kPatch ? "patch" : "sweep"; },
          [](Options& o, std::string_view text) {
            if (text == "patch") {
              o.method = Method::kPatch;
            } else if (text == "sweep") {
              o.method = Method::kSweep;
            } else {
              throw std::invalid_argument("not patch or sweep");
            }
          },
          {"", "the matcher"})
      .Add("inner.ratio", [](auto& o) -> auto& { return o.inner.ratio; }, {"", "a ratio", 0, 1})
      .Add(
          "inner.enabled", [](auto& o) -> auto& { return o.inner.enabled; })
      .Add("inner.deep.ratio", [](auto& o) -> auto& { return o.deeper_owner.ratio; },
           {"m", "nested table"});
  return table;
}

std::string ErrorOf(const std::function<void()>& run) {
  try {
    run();
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(OptionTable, SetOverridesFileOverridesDefaults) {
  const auto file = std::filesystem::path(::testing::TempDir()) / "options.toml";
  std::ofstream(file) << "count = 7\nlabel = \"x\"\n[inner]\nratio = 0.25\n";
  const Options options = Table().Load(Options{}, {file.string()}, {"count=9", "method=sweep"});
  EXPECT_EQ(options.count, 9);
  EXPECT_EQ(options.label, "x");
  EXPECT_EQ(options.method, Method::kSweep);
  EXPECT_DOUBLE_EQ(options.inner.ratio, 0.25);
  EXPECT_TRUE(options.inner.enabled);
}

TEST(OptionTable, TomlTextReadsBackToTheSameOptions) {
  Options changed;
  changed.count = 12;
  changed.label = "with \"quotes\" and \\";
  changed.method = Method::kSweep;
  changed.inner.ratio = 0.1 + 0.2;  // needs all 17 digits
  changed.deeper_owner.ratio = -3;
  const std::string text = Table().ToToml(changed);
  EXPECT_NE(text.find("[inner.deep]\nratio = -3.0\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("count = 12\n"), 0u) << text;

  const auto file = std::filesystem::path(::testing::TempDir()) / "in_force.toml";
  std::ofstream(file) << text;
  const Options read = Table().Load(Options{}, {file.string()}, {});
  EXPECT_EQ(read.count, 12);
  EXPECT_EQ(read.label, changed.label);
  EXPECT_EQ(read.method, Method::kSweep);
  EXPECT_EQ(read.inner.ratio, changed.inner.ratio);
  EXPECT_EQ(read.deeper_owner.ratio, -3);
  EXPECT_EQ(Table().ToToml(read), text);
}

TEST(OptionTable, ErrorsNameTheOptionAndWhereItCameFrom) {
  const OptionTable<Options> table = Table();
  Options options;
  EXPECT_EQ(ErrorOf([&] { table.ApplyTexts(options, {"count=0"}, "--set"); }),
            "avc-test: --set count=0: 0 is below the minimum 1");
  EXPECT_EQ(ErrorOf([&] { table.ApplyTexts(options, {"count=2.5"}, "--set"); }),
            "avc-test: --set count=2.5: '2.5' is not an integer");
  EXPECT_EQ(ErrorOf([&] { table.ApplyTexts(options, {"inner.enabled=yes"}, "job"); }),
            "avc-test: job inner.enabled=yes: 'yes' is not true or false");
  EXPECT_EQ(ErrorOf([&] { table.ApplyTexts(options, {"method=fast"}, "--set"); }),
            "avc-test: --set method=fast: not patch or sweep");
  EXPECT_NE(ErrorOf([&] {
              table.ApplyTexts(options, {"inner.ration=1"}, "--set");
            }).find("inner.ration=1: no such option"),
            std::string::npos);
  EXPECT_NE(ErrorOf([&] {
              table.ApplyTexts(options, {"count"}, "--set");
            }).find("expected SECTION.FIELD=VALUE"),
            std::string::npos);
  // The whole is checked after every assignment is in, and nothing is changed on refusal.
  EXPECT_EQ(ErrorOf([&] {
              table.ApplyTexts(options, {"inner.enabled=false", "count=20"}, "x");
            }),
            "avc-test: count above 10 needs inner.enabled");
  EXPECT_EQ(options.count, 4);
  EXPECT_TRUE(options.inner.enabled);
  EXPECT_NO_THROW(table.ApplyTexts(options, {"count=20", "inner.enabled=false", "count=5"}, "x"));
  EXPECT_EQ(options.count, 5);
}

TEST(OptionTable, YamlFilesReadAsTomlOnesDo) {
  const auto yaml = std::filesystem::path(::testing::TempDir()) / "options.yaml";
  std::ofstream(yaml) << "# the lab's settings\ncount: 7\nlabel: \"x y\"\ninner:\n  ratio: 0.25\n"
                         "  enabled: false\n";
  const auto toml = std::filesystem::path(::testing::TempDir()) / "same.toml";
  std::ofstream(toml) << "count = 7\nlabel = \"x y\"\n[inner]\nratio = 0.25\nenabled = false\n";
  const Options from_yaml = Table().Load(Options{}, {yaml.string()}, {});
  EXPECT_EQ(from_yaml.count, 7);
  EXPECT_EQ(from_yaml.label, "x y");
  EXPECT_DOUBLE_EQ(from_yaml.inner.ratio, 0.25);
  EXPECT_FALSE(from_yaml.inner.enabled);
  EXPECT_EQ(Table().ToToml(from_yaml),
            Table().ToToml(Table().Load(Options{}, {toml.string()}, {})));

  std::ofstream(yaml, std::ios::trunc) << "count: 5\ninner:\n  ratio: 2.0\n";
  EXPECT_EQ(ErrorOf([&] { Table().Load(Options{}, {yaml.string()}, {}); }),
            "avc-test: " + yaml.string() + ":3 inner.ratio=2.0: 2 is above the maximum 1");
  std::ofstream(yaml, std::ios::trunc) << "count: [1, 2]\n";
  EXPECT_NE(ErrorOf([&] { Table().Load(Options{}, {yaml.string()}, {}); }).find(":1: count: "),
            std::string::npos);
  std::ofstream(yaml, std::ios::trunc) << "count: 5\n  label: [\n";
  EXPECT_NE(ErrorOf([&] { Table().Load(Options{}, {yaml.string()}, {}); }).find("options.yaml:"),
            std::string::npos);
  std::ofstream(yaml, std::ios::trunc) << "- count\n";
  EXPECT_NE(ErrorOf([&] {
              Table().Load(Options{}, {yaml.string()}, {});
            }).find("a map of sections and options"),
            std::string::npos);
}

TEST(OptionTable, FileErrorsNameTheLine) {
  const auto file = std::filesystem::path(::testing::TempDir()) / "bad.toml";
  std::ofstream(file) << "count = 5\n\n[inner]\nratio = 2.0\n";
  EXPECT_EQ(ErrorOf([&] { Table().Load(Options{}, {file.string()}, {}); }),
            "avc-test: " + file.string() + ":4 inner.ratio=2.0: 2 is above the maximum 1");
  std::ofstream(file, std::ios::trunc) << "count = [1, 2]\n";
  EXPECT_NE(ErrorOf([&] { Table().Load(Options{}, {file.string()}, {}); }).find(":1: count: "),
            std::string::npos);
  std::ofstream(file, std::ios::trunc) << "count = = 5\n";
  EXPECT_NE(ErrorOf([&] { Table().Load(Options{}, {file.string()}, {}); }).find("bad.toml:1"),
            std::string::npos);
  EXPECT_NE(ErrorOf([&] {
              Table().Load(Options{}, {"/no/such/file.toml"}, {});
            }).find("/no/such/file.toml cannot be read"),
            std::string::npos);
}

TEST(OptionTable, ReferenceListsEveryOptionWithDefaultUnitAndRange) {
  const std::string reference = Table().Reference(Options{});
  EXPECT_NE(reference.find("  count = 4  [1..100]\n      how many\n"), std::string::npos)
      << reference;
  EXPECT_NE(reference.find("  inner.deep.ratio = 0.5  [m]\n"), std::string::npos) << reference;
  EXPECT_THROW(Table().Add(
                   "count", [](auto& o) -> auto& { return o.count; }),
               std::logic_error);
}

struct Timed {
  std::chrono::milliseconds timeout{500};
  std::optional<double> height;
  std::string note = "12";
};

TEST(OptionTable, MillisecondsAndOptionalRealsReadBackThroughToml) {
  OptionTable<Timed> table("avc-timed");
  table.Add("timeout", [](auto& o) -> auto& { return o.timeout; }, {"ms", "", 1, 60000})
      .Add("height", [](auto& o) -> auto& { return o.height; }, {"m", "", -10, 10})
      .Add(
          "note", [](auto& o) -> auto& { return o.note; });
  EXPECT_EQ(table.ToToml(Timed{}), "timeout = 500\nheight = 'none'\nnote = '12'\n");
  Timed changed;
  table.ApplyTexts(changed, {"timeout=250", "height=-0.3"}, "--set");
  EXPECT_EQ(changed.timeout, std::chrono::milliseconds(250));
  EXPECT_EQ(changed.height, -0.3);
  const auto file = std::filesystem::path(::testing::TempDir()) / "timed.toml";
  std::ofstream(file) << table.ToToml(changed);
  const Timed read = table.Load(Timed{}, {file.string()}, {});
  EXPECT_EQ(read.timeout, changed.timeout);
  EXPECT_EQ(read.height, changed.height);
  EXPECT_EQ(read.note, "12");
  table.ApplyTexts(changed, {"height=none"}, "--set");
  EXPECT_FALSE(changed.height.has_value());
  EXPECT_THROW(table.ApplyTexts(changed, {"timeout=0"}, "--set"), ConfigError);
  EXPECT_THROW(table.ApplyTexts(changed, {"height=high"}, "--set"), ConfigError);
}

}  // namespace
}  // namespace avc::config
