// The names of building types in scene files ("office", "apartments", ...): BuildingType in snake case.
#pragma once

#include "model/city_model.h"

#include <optional>
#include <string>

namespace urbis {

/// "generic", "residential", "house", ..., "roof": the enumerator's name in snake case.
const char* buildingTypeName(BuildingType type);

/// The type named `name` (buildingTypeName's), or nullopt.
std::optional<BuildingType> buildingTypeNamed(const std::string& name);

/// Every name, comma-separated, for messages.
std::string buildingTypeNameList();

} // namespace urbis
