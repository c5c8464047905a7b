#include "sim/cell/cell_fixtures.h"

#include <fmt/format.h>

namespace avc::sim {

kinematics::SafetyEnvelope FixturesEnvelope(const CellTruth& cell, const CellFixtures& fixtures) {
  const Eigen::Vector3d& centre = cell.turntable_centre_table;
  const Eigen::Vector3d bench_base =
      cell.T_base_table * (centre - fixtures.turntable_height_m * Eigen::Vector3d::UnitZ());
  const Eigen::Vector3d top_base = cell.T_base_table * centre;
  kinematics::SafetyEnvelope envelope;
  envelope.table_z_base_m = bench_base.z();
  envelope.table_clearance_m = fixtures.clearance_m;
  envelope.keep_out = kinematics::KeepOutCylinder{
      top_base.head<2>(), fixtures.turntable_radius_m + fixtures.clearance_m, bench_base.z(),
      top_base.z() + fixtures.clearance_m};
  return envelope;
}

kinematics::SafetyEnvelope NominalCellEnvelope() { return FixturesEnvelope(NominalCell()); }

std::vector<std::string> RobotEnvelopeArguments(const kinematics::SafetyEnvelope& envelope) {
  std::vector<std::string> args;
  // Four decimals: 0.1 mm, far below every clearance.
  const auto metres = [](double value) { return fmt::format("{:.4f}", value); };
  if (envelope.table_z_base_m) {
    args.insert(args.end(), {"--table-z", metres(*envelope.table_z_base_m), "--table-clearance",
                             metres(envelope.table_clearance_m)});
  }
  if (const auto& k = envelope.keep_out) {
    args.insert(args.end(), {"--keep-out", metres(k->centre_base.x()), metres(k->centre_base.y()),
                             metres(k->radius_m), metres(k->z_min_m), metres(k->z_max_m)});
  }
  return args;
}

}  // namespace avc::sim
