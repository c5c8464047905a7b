#include "bench/bus/bus_bench_receiver.h"

#include <fmt/format.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "core/bus/channels.h"
#include "core/bus/service_runtime.h"
#include "core/products/product_receiver.h"
#include "core/util/log.h"

namespace avc::bench {
namespace {

// Product names are "<phase>/<index>"; the phase is everything before the last '/'.
std::string PhaseOf(const std::string& product_name) {
  const size_t slash = product_name.rfind('/');
  return slash == std::string::npos ? product_name : product_name.substr(0, slash);
}

struct Deliveries {
  std::set<std::string> names;
  std::map<std::string, int64_t> per_phase;
  // Per phase, products handed over again: exactly-once was broken.
  std::map<std::string, int64_t> duplicates_per_phase;
};

void WriteReport(const std::string& path, const Deliveries& delivered,
                 const products::ReceiverStats& stats, const bus::BusStats& bus_stats) {
  nlohmann::json report;
  report["delivered"] = delivered.per_phase;
  report["duplicate_deliveries"] = delivered.duplicates_per_phase;
  report["injected_drops"] = bus_stats.injected_drops;
  report["chunks"] = stats.chunks;
  report["duplicates"] = stats.duplicates;
  report["corrupt"] = stats.corrupt;
  report["invalid"] = stats.invalid;
  std::ofstream out(path, std::ios::trunc);
  out << report.dump() << "\n";
  if (!out) log::Error("cannot write the receiver report {}", path);
}

}  // namespace

int RunBusBenchReceiver(const BusBenchReceiverOptions& options) {
  bus::ServiceRuntime runtime(kBenchReceiverService, options.bus);
  if (options.loss > 0) {
    runtime.bus().InjectReceiveLoss(runtime.bus().FullChannel(channels::kProductBench),
                                    options.loss, options.loss_seed);
  }
  Deliveries delivered;
  products::ProductReceiver receiver(
      runtime.bus(), kBenchReceiverName, std::string(channels::kProductBench),
      [&](const products::Product& product, const bus::RxInfo&) {
        const bool first = delivered.names.insert(product.name).second;
        ++(first ? delivered.per_phase : delivered.duplicates_per_phase)[PhaseOf(product.name)];
      });
  runtime.OnStop([&] {
    WriteReport(options.report_file, delivered, receiver.stats(), runtime.bus().stats());
  });
  runtime.heartbeat().Set(bus::ServiceState::kReady, "receiving benchmark products");
  return runtime.Run();
}

}  // namespace avc::bench
