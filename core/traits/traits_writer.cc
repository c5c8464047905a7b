#include "core/traits/traits_writer.h"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <numbers>
#include <stdexcept>

namespace avc::traits {
namespace {

double Degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

// Shortest text that reads back to the same double: files are reproducible and lossless.
std::string Number(double value) { return fmt::format("{}", value); }

void Row(std::ostream& out, const char* scope, const std::string& id, const char* trait,
         double value, const char* unit) {
  out << scope << ',' << id << ',' << trait << ',' << Number(value) << ',' << unit << '\n';
}

}  // namespace

void WriteTraitsCsv(const PlantTraits& traits, std::ostream& out) {
  out << "scope,id,trait,value,unit\n";
  Row(out, "plant", "", "height", traits.height, "m");
  Row(out, "plant", "", "height_base_z", traits.height_base_z, "m");
  Row(out, "plant", "", "width", traits.width, "m");
  Row(out, "plant", "", "hull_volume", traits.hull_volume, "m3");
  Row(out, "plant", "", "total_area", traits.total_area, "m2");
  Row(out, "plant", "", "faces", static_cast<double>(traits.faces), "count");
  Row(out, "plant", "", "mean_curvature_mean", traits.curvature.mean, "1/m");
  Row(out, "plant", "", "mean_curvature_median", traits.curvature.median, "1/m");
  Row(out, "plant", "", "mean_curvature_p90", traits.curvature.p90, "1/m");
  for (const ClusterTraits& cluster : traits.clusters) {
    const std::string id = std::to_string(cluster.cluster);
    Row(out, "cluster", id, "area", cluster.area, "m2");
    Row(out, "cluster", id, "inclination", Degrees(cluster.inclination), "deg");
    Row(out, "cluster", id, "azimuth", Degrees(cluster.azimuth), "deg");
  }
  for (const GroupTraits& group : traits.groups) {
    Row(out, "group", std::to_string(group.group), "area", group.area, "m2");
  }
}

nlohmann::json TraitsToJson(const PlantTraits& traits) {
  nlohmann::json json;
  json["height_m"] = traits.height;
  json["height_base_z_m"] = traits.height_base_z;
  json["width_m"] = traits.width;
  json["hull_volume_m3"] = traits.hull_volume;
  json["total_area_m2"] = traits.total_area;
  json["faces"] = traits.faces;
  json["mean_curvature_per_m"] = {{"vertices", traits.curvature.vertices},
                                  {"mean", traits.curvature.mean},
                                  {"median", traits.curvature.median},
                                  {"p90", traits.curvature.p90}};
  json["clusters"] = nlohmann::json::array();
  for (const ClusterTraits& cluster : traits.clusters) {
    json["clusters"].push_back(
        {{"cluster", cluster.cluster},
         {"area_m2", cluster.area},
         {"normal", {cluster.normal.x(), cluster.normal.y(), cluster.normal.z()}},
         {"inclination_deg", Degrees(cluster.inclination)},
         {"azimuth_deg", Degrees(cluster.azimuth)}});
  }
  json["groups"] = nlohmann::json::array();
  for (const GroupTraits& group : traits.groups) {
    json["groups"].push_back(
        {{"group", group.group}, {"area_m2", group.area}, {"clusters", group.clusters}});
  }
  return json;
}

void WriteTraitFiles(const PlantTraits& traits, const std::string& directory) {
  const std::filesystem::path dir(directory);
  const auto write = [&](const char* name, const auto& fill) {
    const std::filesystem::path path = dir / name;
    std::ofstream out(path, std::ios::binary);
    if (out) fill(out);
    out.flush();
    if (!out) throw std::runtime_error(fmt::format("traits: cannot write {}", path.string()));
  };
  write("traits.csv", [&](std::ostream& out) { WriteTraitsCsv(traits, out); });
  write("traits.json", [&](std::ostream& out) { out << TraitsToJson(traits).dump(2) << '\n'; });
}

}  // namespace avc::traits
