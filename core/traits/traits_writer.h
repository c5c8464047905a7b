#pragma once

// Plant traits as files: traits.csv (one row per figure: scope, id, trait, value, unit) and a
// JSON document with the same figures. Angles in degrees here (the user's edge), lengths in
// metres.

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include "core/traits/plant_traits.h"

namespace avc::traits {

// Columns: scope (plant | cluster | group), id (empty for the plant), trait, value, unit.
void WriteTraitsCsv(const PlantTraits& traits, std::ostream& out);
nlohmann::json TraitsToJson(const PlantTraits& traits);

// Both files into directory (traits.csv, traits.json). Throws std::runtime_error naming the
// file when it cannot be written.
void WriteTraitFiles(const PlantTraits& traits, const std::string& directory);

}  // namespace avc::traits
