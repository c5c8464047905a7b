#include "tools/avc/bus_flags.h"

namespace avc::cli {

void AddBusFlags(CLI::App* command, bus::BusFlags* flags) {
  command
      ->add_option("--lcm-url", flags->lcm_url,
                   "control LCM URL (default: $AVC_LCM_URL, else $LCM_DEFAULT_URL, else " +
                       std::string(bus::kDefaultControlUrl) + ")")
      ->group("Bus");
  command
      ->add_option("--bulk-url", flags->bulk_url,
                   "bulk LCM URL for products (default: $AVC_BULK_URL, else " +
                       std::string(bus::kDefaultBulkUrl) + ")")
      ->group("Bus");
  command
      ->add_option("--cell", flags->cell,
                   "cell id, the prefix of every channel (default: $AVC_CELL, else cell0)")
      ->group("Bus");
}

}  // namespace avc::cli
