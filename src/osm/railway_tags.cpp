#include "osm/railway_tags.h"

#include "osm/level_tags.h"
#include "osm/tag_parsing.h"

#include <array>
#include <string_view>
#include <utility>

namespace urbis {

namespace {

constexpr float kStandardGauge = 1.435f, kMetreGauge = 1.0f;  // m
constexpr int kMinGaugeMm = 300, kMaxGaugeMm = 3000;

} // namespace

std::optional<RailKind> railKindOf(const char* railway) {
    static constexpr std::array<std::pair<std::string_view, RailKind>, 5> kKinds = {{
        {"rail", RailKind::Rail}, {"light_rail", RailKind::LightRail}, {"tram", RailKind::Tram},
        {"subway", RailKind::Subway}, {"narrow_gauge", RailKind::Narrow}}};
    if (!railway) return std::nullopt;
    for (const auto& [name, kind] : kKinds)
        if (trim(railway) == name) return kind;
    return std::nullopt;
}

Railway railwayFromTags(const TagLookup& tag, RailKind kind, int64_t osmId, std::map<std::string, uint64_t>& issues) {
    Railway r;
    r.osmId = osmId;
    r.kind = kind;
    r.gauge = kind == RailKind::Narrow ? kMetreGauge : kStandardGauge;
    if (const char* gauge = tag("gauge")) {
        const std::string_view first = trim(std::string_view(gauge).substr(0, std::string_view(gauge).find(';')));
        const std::optional<int> mm = parseInteger(first);
        if (mm && *mm >= kMinGaugeMm && *mm <= kMaxGaugeMm) r.gauge = float(*mm) * 0.001f;
        else ++issues["railway_bad_gauge_tag"];
    }
    const char* embedded = tag("embedded");
    const std::string_view e = embedded ? trim(embedded) : "";
    r.embedded = oneOf(e, {"yes", "partial"}) || (kind == RailKind::Tram && e != "no");
    assignLevel(levelFromTags(tag, "railway_bad_layer_tag", issues), r);
    return r;
}

} // namespace urbis
