#include "osm/level_tags.h"

#include "osm/tag_parsing.h"

#include <algorithm>
#include <optional>
#include <string_view>

namespace urbis {

namespace {

constexpr int kMinLayer = -5, kMaxLayer = 5;

bool isSet(const char* value) { return value && trim(value) != "no"; }

} // namespace

LevelTags levelFromTags(const TagLookup& tag, const char* badLayerIssue, std::map<std::string, uint64_t>& issues) {
    LevelTags level;
    if (const char* layer = tag("layer")) {
        const std::optional<int> value = parseInteger(layer);
        if (!value || *value < kMinLayer || *value > kMaxLayer) ++issues[badLayerIssue];
        if (value) level.layer = std::clamp(*value, kMinLayer, kMaxLayer);
    }
    level.bridge = isSet(tag("bridge"));
    level.tunnel = isSet(tag("tunnel"));
    const char* covered = tag("covered");
    level.covered = covered && isYes(trim(covered));
    const char* location = tag("location");
    level.underground = location && listHolds(location, "underground");
    return level;
}

} // namespace urbis
