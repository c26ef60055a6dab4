#include "description/building_type_names.h"

#include <iterator>
#include <utility>

namespace urbis {

namespace {

using T = BuildingType;
constexpr std::pair<const char*, BuildingType> kNames[] = {
    {"generic", T::Generic},     {"residential", T::Residential}, {"house", T::House},       {"apartments", T::Apartments},
    {"commercial", T::Commercial}, {"retail", T::Retail},         {"office", T::Office},     {"industrial", T::Industrial},
    {"warehouse", T::Warehouse}, {"religious", T::Religious},     {"civic", T::Civic},       {"school", T::School},
    {"hospital", T::Hospital},   {"hotel", T::Hotel},             {"garage", T::Garage},     {"shed", T::Shed},
    {"roof", T::Roof}};
static_assert(std::size(kNames) == size_t(T::Roof) + 1, "a name for every BuildingType");

} // namespace

const char* buildingTypeName(BuildingType type) {
    for (const auto& [name, t] : kNames)
        if (t == type) return name;
    return "generic";
}

std::optional<BuildingType> buildingTypeNamed(const std::string& name) {
    for (const auto& [n, t] : kNames)
        if (name == n) return t;
    return std::nullopt;
}

std::string buildingTypeNameList() {
    std::string list;
    for (const auto& [name, t] : kNames) list += (list.empty() ? "" : ", ") + std::string(name);
    return list;
}

} // namespace urbis
