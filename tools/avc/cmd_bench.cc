// avc bench: runs one benchmark by name (see BENCHMARKS.md for what each measures).

#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "bench/registry.h"
#include "tools/avc/commands.h"
#include "tools/avc/help_formatter.h"

namespace avc::cli {
namespace {

struct BenchArgs {
  std::string name;  // the first argument that is not one of ours
  bool list = false;
  bool help = false;
};

// One line per benchmark: its name and what it measures.
std::string BenchmarkList(const std::string& indent) {
  size_t width = 0;
  for (const bench::Benchmark& benchmark : bench::AllBenchmarks()) {
    width = std::max(width, benchmark.name.size());
  }
  std::string list;
  for (const bench::Benchmark& benchmark : bench::AllBenchmarks()) {
    list += fmt::format("{}{:<{}}  {}\n", indent, benchmark.name, width, benchmark.description);
  }
  return list;
}

void PrintBenchmarks() { std::cout << BenchmarkList(""); }

// NAME and the benchmark's own options are taken by hand (a prefix command), so CLI11 cannot
// build the usage line from declared options: it is spelled out here.
class BenchHelpFormatter : public SummaryListingFormatter {
 public:
  std::string make_usage(const CLI::App* /*command*/, std::string name) const override {
    return "Usage: " + name + " [--list] NAME [BENCHMARK OPTIONS]\n";
  }
};

}  // namespace

void RegisterBench(CLI::App& root, int* exit_code) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* command = root.add_subcommand(
      "bench",
      "Run a benchmark: our method against its baselines on the same input, in one run.\n"
      "Arguments after NAME go to the benchmark ('avc bench NAME --help' lists them).\n"
      "Results are printed as a table; --json adds one JSON line. Figures: BENCHMARKS.md.");
  command->formatter(std::make_shared<BenchHelpFormatter>());
  command->footer("Benchmarks (NAME):\n" + BenchmarkList("  "));
  command->add_flag("--list", args->list, "list the benchmarks and exit");
  // Everything after NAME, --help included, belongs to the benchmark.
  command->prefix_command();
  command->set_help_flag();
  command->add_flag("-h,--help", args->help, "print this help (after NAME: the benchmark's)");
  command->callback([args, exit_code, command] {
    std::vector<std::string> rest = command->remaining();
    if (!rest.empty()) {
      args->name = rest.front();
      rest.erase(rest.begin());
    }
    if (args->help && args->name.empty()) {
      std::cout << command->help("avc");
      return;
    }
    if (args->list) {
      PrintBenchmarks();
      return;
    }
    if (args->name.empty()) {
      std::cerr << "avc bench: name a benchmark (avc bench NAME, avc bench --help); there are:\n";
      PrintBenchmarks();
      *exit_code = 2;
      return;
    }
    const bench::Benchmark* benchmark = bench::FindBenchmark(args->name);
    if (benchmark == nullptr) {
      std::cerr << "avc bench: no benchmark named '" << args->name << "'; there are:\n";
      PrintBenchmarks();
      *exit_code = 2;
      return;
    }
    try {
      *exit_code = benchmark->run(rest);
    } catch (const std::exception& e) {
      std::cerr << "avc bench " << args->name << ": " << e.what() << "\n";
      *exit_code = 1;
    }
  });
}

}  // namespace avc::cli
