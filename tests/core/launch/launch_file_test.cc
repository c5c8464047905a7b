// Launch files: TOML and YAML give the same spec, defaults and relative paths are resolved
// against the file's folder, hosts filter processes, and every bad input names file and line.

#include "core/launch/launch_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <functional>

#include "core/launch/find_program.h"
#include "tests/support/test_support.h"

namespace avc::launch {
namespace {

namespace fs = std::filesystem;
using std::chrono::milliseconds;

constexpr char kToml[] = R"(# The same launch file as kYaml, line for line where it can be.
log_dir = "out/logs"

[env]
AVC_CELL = "cellx"
SHARED = "file"

[[process]]
name = "alpha"
command = "tools/run.sh"
args = ["--rate", "10", "two words"]
host = "lab-pc-1"
env = { SHARED = "alpha", EXTRA = "1" }
restart = "always"
stop_timeout = 2.5
working_dir = "data"

[[process]]
name = "beta"
command = "sh"
restart = "never"
stop_timeout = 1
)";

constexpr char kYaml[] = R"(# The same launch file as kToml.
log_dir: out/logs
env:
  AVC_CELL: cellx
  SHARED: file
process:
  - name: alpha
    command: tools/run.sh
    args: ["--rate", "10", "two words"]
    host: lab-pc-1
    env: {SHARED: alpha, EXTRA: "1"}
    restart: always
    stop_timeout: 2.5
    working_dir: data
  - name: beta
    command: sh
    restart: never
    stop_timeout: 1
)";

// The spec without what necessarily differs between two formats: file name and line numbers.
LaunchSpec WithoutSourcePositions(LaunchSpec spec) {
  spec.file.clear();
  for (ProcessSpec& process : spec.processes) {
    process.line = 0;
    process.command_line = 0;
  }
  return spec;
}

TEST(LaunchFile, TomlIsReadWithEveryKey) {
  const LaunchSpec spec = ParseLaunchFile(kToml, "/srv/cell/demo.toml");
  EXPECT_EQ(spec.file, "/srv/cell/demo.toml");
  EXPECT_EQ(spec.log_dir, "/srv/cell/out/logs");
  EXPECT_EQ(spec.env,
            (std::map<std::string, std::string>{{"AVC_CELL", "cellx"}, {"SHARED", "file"}}));
  ASSERT_EQ(spec.processes.size(), 2u);
  const ProcessSpec& alpha = spec.processes[0];
  EXPECT_EQ(alpha.name, "alpha");
  EXPECT_EQ(alpha.command, "/srv/cell/tools/run.sh");
  EXPECT_EQ(alpha.args, (std::vector<std::string>{"--rate", "10", "two words"}));
  EXPECT_EQ(alpha.host, "lab-pc-1");
  EXPECT_EQ(alpha.env, (std::map<std::string, std::string>{{"SHARED", "alpha"}, {"EXTRA", "1"}}));
  EXPECT_EQ(alpha.restart, RestartPolicy::kAlways);
  EXPECT_EQ(alpha.stop_timeout, milliseconds(2500));
  EXPECT_EQ(alpha.working_dir, "/srv/cell/data");
  EXPECT_EQ(alpha.line, 8);
  EXPECT_EQ(alpha.command_line, 10);
  const ProcessSpec& beta = spec.processes[1];
  EXPECT_EQ(beta.name, "beta");
  EXPECT_EQ(beta.command, "sh") << "bare names are resolved later, by ResolveCommands";
  EXPECT_EQ(beta.restart, RestartPolicy::kNever);
  EXPECT_EQ(beta.stop_timeout, milliseconds(1000));
  EXPECT_EQ(beta.line, 18);
  EXPECT_EQ(beta.command_line, 20);
}

TEST(LaunchFile, YamlGivesTheSameSpecAsToml) {
  const LaunchSpec toml = ParseLaunchFile(kToml, "/srv/cell/demo.toml");
  const LaunchSpec yaml = ParseLaunchFile(kYaml, "/srv/cell/demo.yaml");
  EXPECT_EQ(yaml.file, "/srv/cell/demo.yaml");
  EXPECT_EQ(WithoutSourcePositions(yaml), WithoutSourcePositions(toml));
  ASSERT_EQ(yaml.processes.size(), 2u);
  EXPECT_EQ(yaml.processes[0].line, 7);
  EXPECT_EQ(yaml.processes[0].command_line, 8);
  EXPECT_EQ(yaml.processes[1].line, 15);
  EXPECT_EQ(yaml.processes[1].command_line, 16);
  // .yml is YAML too.
  EXPECT_EQ(WithoutSourcePositions(ParseLaunchFile(kYaml, "/srv/cell/demo.yml")),
            WithoutSourcePositions(yaml));
}

TEST(LaunchFile, DemoFilesAreValidAndTheSameInBothFormats) {
  const fs::path launch = testing::SourceDir() / "launch";
  const LaunchSpec toml = LoadLaunchFile((launch / "demo-foundation.toml").string());
  const LaunchSpec yaml = LoadLaunchFile((launch / "demo-foundation.yaml").string());
  EXPECT_EQ(WithoutSourcePositions(yaml), WithoutSourcePositions(toml));
  EXPECT_EQ(toml.log_dir, (launch / "logs").string());
  ASSERT_EQ(toml.processes.size(), 2u);
  EXPECT_EQ(toml.processes[0].name, "recorder");
  EXPECT_EQ(toml.processes[0].command, "avc");
  EXPECT_EQ(toml.processes[0].args.at(0), "record");
  EXPECT_EQ(toml.processes[0].working_dir, toml.log_dir);
  EXPECT_EQ(toml.processes[1].name, "collector");
  EXPECT_EQ(toml.processes[1].args.at(0), "collect");
  EXPECT_EQ(toml.processes[1].host, "") << "the demo runs on any host";
}

TEST(LaunchFile, SimulatedCellLaunchFilesAreValid) {
  const fs::path launch = testing::SourceDir() / "launch";
  using V = std::vector<std::string>;
  // A scan needs the reconstruction stages; a calibration does not.
  for (const auto& [file, expected] : std::vector<std::pair<std::string, V>>{
           {"sim-cell.toml",
            {"sim", "robot", "turntable", "camera", "planner", "builder", "clusterer", "surfacer",
             "record"}},
           {"sim-calibration.toml", {"sim", "robot", "turntable", "camera", "record"}}}) {
    SCOPED_TRACE(file);
    const LaunchSpec spec = LoadLaunchFile((launch / file).string());
    V subcommands;
    for (const auto& process : spec.processes) {
      EXPECT_EQ(process.name, process.args.at(0) == "record" ? "recorder" : process.args.at(0));
      subcommands.push_back(process.args.at(0));
    }
    EXPECT_EQ(subcommands, expected);
  }
}

TEST(LaunchFile, DefaultsApplyToKeysLeftOut) {
  for (const auto& [text, file] : std::vector<std::pair<std::string, std::string>>{
           {"[[process]]\nname = \"p\"\ncommand = \"sh\"\n", "/a/b/min.toml"},
           {"process:\n  - name: p\n    command: sh\n", "/a/b/min.yaml"}}) {
    SCOPED_TRACE(file);
    const LaunchSpec spec = ParseLaunchFile(text, file);
    EXPECT_EQ(spec.log_dir, "/a/b/logs");
    EXPECT_TRUE(spec.env.empty());
    ASSERT_EQ(spec.processes.size(), 1u);
    const ProcessSpec& p = spec.processes[0];
    EXPECT_EQ(p.name, "p");
    EXPECT_EQ(p.command, "sh");
    EXPECT_TRUE(p.args.empty());
    EXPECT_EQ(p.host, "");
    EXPECT_TRUE(p.env.empty());
    EXPECT_EQ(p.restart, RestartPolicy::kOnFailure);
    EXPECT_EQ(p.stop_timeout, milliseconds(5000));
    EXPECT_EQ(p.working_dir, "");
  }
}

TEST(LaunchFile, RelativePathsAreResolvedAgainstTheFilesFolder) {
  const LaunchSpec spec = ParseLaunchFile(
      "log_dir = \"/var/log/avc\"\n"
      "[[process]]\nname = \"up\"\ncommand = \"../bin/tool\"\nworking_dir = \".\"\n"
      "[[process]]\nname = \"abs\"\ncommand = \"/usr/bin/env\"\nworking_dir = \"/tmp/x/../y\"\n"
      "[[process]]\nname = \"dot\"\ncommand = \"./run\"\nworking_dir = \"sub/dir/\"\n",
      "/srv/cell/launch/x.toml");
  EXPECT_EQ(spec.log_dir, "/var/log/avc");
  ASSERT_EQ(spec.processes.size(), 3u);
  EXPECT_EQ(spec.processes[0].command, "/srv/cell/bin/tool");
  EXPECT_EQ(fs::path(spec.processes[0].working_dir), fs::path("/srv/cell/launch/"));
  EXPECT_EQ(spec.processes[1].command, "/usr/bin/env");
  EXPECT_EQ(spec.processes[1].working_dir, "/tmp/y");
  EXPECT_EQ(spec.processes[2].command, "/srv/cell/launch/run");
  EXPECT_EQ(fs::path(spec.processes[2].working_dir), fs::path("/srv/cell/launch/sub/dir/"));

  // A relative launch file name is relative to the current directory.
  const LaunchSpec relative =
      ParseLaunchFile("[[process]]\nname = \"p\"\ncommand = \"bin/p\"\n", "launch/rel.toml");
  EXPECT_EQ(relative.log_dir, (fs::current_path() / "launch/logs").lexically_normal().string());
  EXPECT_EQ(relative.processes[0].command,
            (fs::current_path() / "launch/bin/p").lexically_normal().string());
}

TEST(LaunchFile, ProcessEnvIsKeptApartFromTheFileEnv) {
  // The supervisor merges them at start (process over file); the spec keeps both as written.
  const LaunchSpec spec = ParseLaunchFile(kToml, "/srv/cell/demo.toml");
  EXPECT_EQ(spec.env.at("SHARED"), "file");
  EXPECT_EQ(spec.processes[0].env.at("SHARED"), "alpha");
  EXPECT_EQ(spec.processes[0].env.count("AVC_CELL"), 0u);
  EXPECT_TRUE(spec.processes[1].env.empty());
}

TEST(LaunchFile, StarAndLocalhostMeanEveryHost) {
  const LaunchSpec spec = ParseLaunchFile(
      "[[process]]\nname = \"a\"\ncommand = \"sh\"\nhost = \"*\"\n"
      "[[process]]\nname = \"b\"\ncommand = \"sh\"\nhost = \"LocalHost\"\n",
      "/x/hosts.toml");
  EXPECT_EQ(spec.processes[0].host, "");
  EXPECT_EQ(spec.processes[1].host, "");
}

TEST(LaunchFile, LoadReadsTheFileAndNamesItWhenUnreadable) {
  testing::TempDir dir("avc-launch");
  const fs::path file = dir / "cell.yaml";
  testing::WriteFile(file, kYaml);
  const LaunchSpec spec = LoadLaunchFile(file.string());
  EXPECT_EQ(spec.file, file.string());
  EXPECT_EQ(spec.log_dir, (dir.path() / "out/logs").string());
  EXPECT_EQ(spec.processes.at(0).command, (dir.path() / "tools/run.sh").string());

  const std::string missing = (dir / "missing.toml").string();
  try {
    LoadLaunchFile(missing);
    FAIL() << "no error for a missing file";
  } catch (const LaunchFileError& e) {
    EXPECT_EQ(e.file(), missing);
    EXPECT_EQ(e.line(), 0);
    EXPECT_EQ(std::string(e.what()).rfind(missing + ": cannot read", 0), 0u) << e.what();
  }
}

// Parses text as file and checks the error names file and line and says problem.
void ExpectError(const std::string& text, const std::string& file, int line,
                 const std::vector<std::string>& problem_parts) {
  SCOPED_TRACE(file + ":\n" + text);
  try {
    ParseLaunchFile(text, file);
    ADD_FAILURE() << "no error";
  } catch (const LaunchFileError& e) {
    EXPECT_EQ(e.file(), file);
    EXPECT_EQ(e.line(), line) << e.what();
    const std::string prefix = line > 0 ? file + ":" + std::to_string(line) + ": " : file + ": ";
    EXPECT_EQ(std::string(e.what()), prefix + e.problem());
    EXPECT_FALSE(e.problem().empty());
    for (const std::string& part : problem_parts) {
      EXPECT_NE(e.problem().find(part), std::string::npos)
          << "'" << part << "' missing from: " << e.what();
    }
  }
}

TEST(LaunchFileErrors, SyntaxError) {
  ExpectError("log_dir = \"x\"\n[[process]]\nname = \"p\ncommand = \"sh\"\n", "/d/bad.toml", 3, {});
  ExpectError("[[process]]\nname = \"p\"\ncommand = \"sh\"\nargs = [\"a\",\n", "/d/bad.toml", 4,
              {});
  ExpectError("[[process]\nname = \"p\"\n", "/d/bad.toml", 1, {});
  ExpectError("process:\n  - name: p\n    command: sh\n    args: [a, b\n", "/d/bad.yaml", 5, {});
  ExpectError("process:\n  - name: p\n    command: sh: -c\n", "/d/bad.yaml", 3, {});
  ExpectError("log_dir: x\nprocess:\n  - name: p\n   command: sh\n", "/d/bad.yaml", 4, {});
}

TEST(LaunchFileErrors, UnknownKey) {
  ExpectError("[[process]]\nname = \"p\"\ncomand = \"sh\"\n", "/d/k.toml", 3,
              {"unknown key 'comand'", "[[process]]", "did you mean 'command'"});
  ExpectError("process:\n  - name: p\n    command: sh\n    restrat: never\n", "/d/k.yaml", 4,
              {"unknown key 'restrat'", "did you mean 'restart'"});
  ExpectError("logdir = \"x\"\n[[process]]\nname = \"p\"\ncommand = \"sh\"\n", "/d/k.toml", 1,
              {"unknown key 'logdir'", "the launch file", "did you mean 'log_dir'"});
  ExpectError("process:\n  - name: p\n    command: sh\nprocesses: []\n", "/d/k.yml", 4,
              {"unknown key 'processes'", "allowed keys: log_dir, env, process"});
}

TEST(LaunchFileErrors, WrongType) {
  ExpectError("[[process]]\nname = \"p\"\ncommand = \"sh\"\nargs = \"-c true\"\n", "/d/t.toml", 4,
              {"args must be a list of strings, not a string"});
  ExpectError("[[process]]\nname = \"p\"\ncommand = \"sh\"\nargs = [\n  \"-c\",\n  3,\n]\n",
              "/d/t.toml", 6, {"args[1] must be a string, not a number"});
  ExpectError("[[process]]\nname = \"p\"\ncommand = 7\n", "/d/t.toml", 3,
              {"command must be a string, not a number"});
  ExpectError("[[process]]\nname = \"p\"\ncommand = \"sh\"\nstop_timeout = \"soon\"\n", "/d/t.toml",
              4, {"stop_timeout must be a number"});
  ExpectError("process:\n  - name: p\n    command: sh\n    stop_timeout: soon\n", "/d/t.yaml", 4,
              {"stop_timeout must be a number, not 'soon'"});
  ExpectError("process:\n  - name: p\n    command: sh\n    env: [A, B]\n", "/d/t.yaml", 4,
              {"env must be a table", "not a list"});
  ExpectError("process:\n  - name: p\n    command:\n", "/d/t.yaml", 3,
              {"command must be a string, not empty"});
  ExpectError("process = \"p\"\n", "/d/t.toml", 1, {"process must be a list of tables"});
  ExpectError("process:\n  - just-a-name\n", "/d/t.yaml", 2,
              {"each process must be a table, not a string"});
  ExpectError("[env]\nPATH = 1\n[[process]]\nname = \"p\"\ncommand = \"sh\"\n", "/d/t.toml", 2,
              {"env.PATH must be a string, not a number"});
}

TEST(LaunchFileErrors, DuplicateProcessName) {
  ExpectError(
      "[[process]]\nname = \"cam\"\ncommand = \"sh\"\n\n[[process]]\nname = \"cam\"\n"
      "command = \"sh\"\n",
      "/d/dup.toml", 6, {"duplicate process name 'cam'", "first used on line 2"});
  ExpectError("process:\n  - name: cam\n    command: sh\n  - command: sh\n    name: cam\n",
              "/d/dup.yaml", 5, {"duplicate process name 'cam'", "first used on line 2"});
}

TEST(LaunchFileErrors, MissingCommandOrName) {
  ExpectError("log_dir = \"x\"\n\n[[process]]\nname = \"p\"\nargs = [\"x\"]\n", "/d/m.toml", 3,
              {"process 'p' has no command"});
  ExpectError("log_dir: x\nprocess:\n  - name: p\n    args: [x]\n", "/d/m.yaml", 3,
              {"process 'p' has no command"});
  ExpectError("[[process]]\ncommand = \"sh\"\n", "/d/m.toml", 1, {"has no name"});
  ExpectError("log_dir = \"x\"\n", "/d/m.toml", 1, {"no processes"});
  ExpectError("process: []\n", "/d/m.yaml", 1, {"the process list is empty"});
}

TEST(LaunchFileErrors, BadRestartValue) {
  ExpectError("[[process]]\nname = \"p\"\ncommand = \"sh\"\nrestart = \"sometimes\"\n", "/d/r.toml",
              4, {"restart must be \"always\", \"on-failure\" or \"never\"", "not \"sometimes\""});
  ExpectError("process:\n  - name: p\n    command: sh\n\n    restart: on_failure\n", "/d/r.yaml", 5,
              {"not \"on_failure\""});
}

TEST(LaunchFileErrors, OtherBadValues) {
  ExpectError("[[process]]\nname = \"p\"\ncommand = \"sh -c true\"\n", "/d/v.toml", 3,
              {"contains spaces"});
  ExpectError("[[process]]\nname = \"a/b\"\ncommand = \"sh\"\n", "/d/v.toml", 2,
              {"process name 'a/b'"});
  ExpectError("[[process]]\nname = \"p\"\ncommand = \"sh\"\nstop_timeout = -1\n", "/d/v.toml", 4,
              {"stop_timeout must be a number of seconds above 0"});
  ExpectError("[[process]]\nname = \"p\"\ncommand = \"sh\"\nenv = { 1X = \"y\" }\n", "/d/v.toml", 4,
              {"'1X'", "not a valid environment variable name"});
  ExpectError("[[process]]\nname = \"p\"\ncommand = \"\"\n", "/d/v.toml", 3,
              {"command must not be empty"});
  ExpectError("process:\n  - name: p\n    command: sh\n    command: bash\n", "/d/v.yaml", 4,
              {"duplicate key 'command'", "first on line 3"});
  ExpectError("whatever", "/d/v.json", 0, {"unknown launch file type '.json'"});
}

TEST(HostMatches, EmptyMatchesEveryHostOthersMatchByNameIgnoringCaseAndDomain) {
  EXPECT_TRUE(HostMatches("", "anything"));
  EXPECT_TRUE(HostMatches("lab-pc-1", "lab-pc-1"));
  EXPECT_TRUE(HostMatches("LAB-PC-1", "lab-pc-1"));
  EXPECT_TRUE(HostMatches("lab-pc-1", "lab-pc-1.lab.example"));
  EXPECT_TRUE(HostMatches("lab-pc-1.lab.example", "Lab-PC-1"));
  EXPECT_FALSE(HostMatches("lab-pc-1", "lab-pc-10"));
  EXPECT_FALSE(HostMatches("lab-pc-10", "lab-pc-1"));
  EXPECT_FALSE(HostMatches("lab-pc-1", "lab-pc-2.lab.example"));
  EXPECT_FALSE(HostMatches("lab-pc-1", ""));
}

TEST(HostMatches, ForHostKeepsOnlyThatHostsProcesses) {
  const LaunchSpec spec = ParseLaunchFile(
      "process:\n"
      "  - {name: everywhere, command: sh}\n"
      "  - {name: one, command: sh, host: lab-pc-1}\n"
      "  - {name: two, command: sh, host: LAB-PC-2.lab.example}\n"
      "  - {name: star, command: sh, host: '*'}\n",
      "/x/hosts.yaml");
  auto names = [](const LaunchSpec& s) {
    std::vector<std::string> list;
    for (const ProcessSpec& p : s.processes) list.push_back(p.name);
    return list;
  };
  EXPECT_EQ(names(ForHost(spec, "lab-pc-2")),
            (std::vector<std::string>{"everywhere", "two", "star"}));
  EXPECT_EQ(names(ForHost(spec, "lab-pc-1.lab.example")),
            (std::vector<std::string>{"everywhere", "one", "star"}));
  EXPECT_EQ(names(ForHost(spec, "elsewhere")), (std::vector<std::string>{"everywhere", "star"}));
  const LaunchSpec filtered = ForHost(spec, "lab-pc-1");
  EXPECT_EQ(filtered.file, spec.file);
  EXPECT_EQ(filtered.log_dir, spec.log_dir);
}

void MakeExecutable(const fs::path& path, bool executable = true) {
  testing::WriteFile(path, "#!/bin/sh\nexit 0\n");
  ASSERT_EQ(chmod(path.c_str(), executable ? 0755 : 0644), 0);
}

TEST(ResolveCommands, BinDirFirstThenPathAndErrorsAtTheCommandLine) {
  testing::TempDir dir("avc-launch");
  fs::create_directories(dir / "bin");
  fs::create_directories(dir / "extra");
  MakeExecutable(dir / "bin" / "sh");  // next to avc: wins over /bin/sh
  MakeExecutable(dir / "bin" / "mytool");
  MakeExecutable(dir / "extra" / "othertool");
  MakeExecutable(dir / "local.sh");
  MakeExecutable(dir / "notexec.sh", false);
  const std::string file = (dir / "cell.toml").string();
  const std::string extra_path = (dir / "extra").string();
  testing::WriteFile(file, R"([[process]]
name = "a"
command = "mytool"
[[process]]
name = "b"
command = "sh"
[[process]]
name = "c"
command = "env"
[[process]]
name = "e"
command = "./local.sh"
[[process]]
name = "d"
command = "othertool"
env = { PATH = ")" + extra_path +
                               "\" }\n");
  LaunchSpec spec = LoadLaunchFile(file);
  ResolveCommands(spec, dir / "bin");
  EXPECT_EQ(spec.processes[0].command, (dir / "bin" / "mytool").string());
  EXPECT_EQ(spec.processes[1].command, (dir / "bin" / "sh").string());
  const fs::path env = spec.processes[2].command;
  EXPECT_TRUE(env.is_absolute()) << env;
  EXPECT_EQ(env.filename(), "env");
  EXPECT_TRUE(IsExecutableFile(env));
  EXPECT_EQ(spec.processes[3].command, (dir / "local.sh").string());
  EXPECT_EQ(spec.processes[4].command, (dir / "extra" / "othertool").string());

  // Without a bin folder bare names come from PATH.
  LaunchSpec again = LoadLaunchFile(file);
  again.processes.erase(again.processes.begin());  // mytool is only in bin
  ResolveCommands(again, {});
  EXPECT_NE(again.processes[0].command, (dir / "bin" / "sh").string());
  EXPECT_EQ(fs::path(again.processes[0].command).filename(), "sh");

  auto expect_error = [&](const std::string& text, int line,
                          const std::vector<std::string>& parts) {
    SCOPED_TRACE(text);
    const std::string bad_file = (dir / "bad.toml").string();
    testing::WriteFile(bad_file, text);
    LaunchSpec bad = LoadLaunchFile(bad_file);
    try {
      ResolveCommands(bad, dir / "bin");
      ADD_FAILURE() << "no error";
    } catch (const LaunchFileError& e) {
      EXPECT_EQ(e.file(), bad_file);
      EXPECT_EQ(e.line(), line) << e.what();
      for (const std::string& part : parts) {
        EXPECT_NE(e.problem().find(part), std::string::npos) << part << " in " << e.what();
      }
    }
  };
  expect_error(
      "[[process]]\nname = \"ok\"\ncommand = \"sh\"\n[[process]]\nname = \"x\"\n\n"
      "command = \"no-such-tool-xyz\"\n",
      7, {"'no-such-tool-xyz'", "process 'x'", "PATH"});
  expect_error("[[process]]\nname = \"y\"\ncommand = \"./notexec.sh\"\n", 3,
               {(dir / "notexec.sh").string(), "not an executable file"});
  expect_error("[[process]]\nname = \"z\"\ncommand = \"./missing.sh\"\n", 3,
               {"not an executable file"});
  // The file's PATH counts when looking a bare name up.
  expect_error("[env]\nPATH = \"/nonexistent\"\n[[process]]\nname = \"w\"\ncommand = \"env\"\n", 5,
               {"'env'", "/nonexistent"});
}

}  // namespace
}  // namespace avc::launch
