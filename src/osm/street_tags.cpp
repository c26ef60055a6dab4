#include "osm/street_tags.h"

#include "osm/level_tags.h"
#include "osm/tag_parsing.h"

#include <algorithm>
#include <array>
#include <utility>
#include <string_view>

namespace urbis {

namespace {

constexpr int kMaxLanes = 16;
constexpr float kMaxWidth = 100.0f, kMaxSidewalkWidth = 20.0f; // m

struct ClassDefaults {
    HighwayClass highway;
    float width;     // m
    int lanes;
    float laneWidth; // m
};
constexpr std::array<ClassDefaults, 16> kClassDefaults = {{
    {HighwayClass::Motorway, 11.0f, 3, 3.5f},      {HighwayClass::Trunk, 10.0f, 3, 3.5f},
    {HighwayClass::Primary, 9.0f, 2, 3.25f},       {HighwayClass::Secondary, 8.0f, 2, 3.25f},
    {HighwayClass::Tertiary, 7.0f, 2, 3.0f},       {HighwayClass::Unclassified, 6.0f, 2, 3.0f},
    {HighwayClass::Residential, 6.0f, 2, 3.0f},    {HighwayClass::Service, 4.0f, 1, 3.0f},
    {HighwayClass::LivingStreet, 5.0f, 1, 3.0f},   {HighwayClass::Pedestrian, 5.0f, 1, 3.0f},
    {HighwayClass::Footway, 2.0f, 1, 3.0f},        {HighwayClass::Cycleway, 2.0f, 1, 3.0f},
    {HighwayClass::Path, 1.5f, 1, 3.0f},           {HighwayClass::Steps, 2.0f, 1, 3.0f},
    {HighwayClass::Track, 3.0f, 1, 3.0f},          {HighwayClass::Other, 4.0f, 1, 3.0f}}};

ClassDefaults defaultsOf(HighwayClass highway) {
    for (const ClassDefaults& d : kClassDefaults)
        if (d.highway == highway) return d;
    return kClassDefaults.back();
}

bool is(const char* value, std::string_view name) { return value && trim(value) == name; }

/// A lane count in [minimum, kMaxLanes] from `key`; -1 when untagged or unusable (then counted).
int lanesTag(const TagLookup& tag, const char* key, int minimum, std::map<std::string, uint64_t>& issues) {
    const char* value = tag(key);
    if (!value) return -1;
    const std::optional<int> n = parseInteger(value);
    if (n && *n >= minimum && *n <= kMaxLanes) return *n;
    ++issues["road_bad_lanes_tag"];
    return -1;
}

void readLanesAndWidth(const TagLookup& tag, bool reversed, Road& r, std::map<std::string, uint64_t>& issues) {
    const ClassDefaults defaults = defaultsOf(r.highway);
    const int lanes = lanesTag(tag, "lanes", 1, issues);
    int forward = lanesTag(tag, "lanes:forward", 0, issues);
    int backward = lanesTag(tag, "lanes:backward", 0, issues);
    if (reversed) std::swap(forward, backward); // the centerline is flipped to the way's one direction
    r.lanesForward = std::max(forward, 0);
    r.lanesBackward = std::max(backward, 0);
    const bool directional = forward >= 0 || backward >= 0;
    const int untaggedSide = r.oneway ? 0 : 1;
    if (lanes > 0) r.lanes = lanes;
    else if (directional) r.lanes = std::max(1, (forward >= 0 ? forward : untaggedSide) + (backward >= 0 ? backward : untaggedSide));
    else r.lanes = r.oneway ? 1 : defaults.lanes;
    r.width = (lanes > 0 || directional) ? float(r.lanes) * defaults.laneWidth : defaults.width;
    if (const char* value = tag("width")) {
        const std::optional<double> width = parseLength(value);
        if (width && *width > 0.0 && *width < kMaxWidth) r.width = float(*width);
        else ++issues["road_bad_width_tag"];
    }
}

/// One side's sidewalk as tagged: unknown, a sidewalk drawn with the road, none, or a separate way.
enum class Side : uint8_t { Unknown, Yes, No, Separate };

Side sideOf(std::string_view value) {
    const std::string_view v = trim(value);
    if (oneOf(v, {"yes", "both", "left", "right"})) return Side::Yes;
    if (oneOf(v, {"no", "none"})) return Side::No;
    if (v == "separate") return Side::Separate;
    return Side::Unknown;
}

/// The combined Sidewalk of both sides: a drawn side wins over a separate one (that one is its
/// own footway), a separate one over none.
Sidewalk combine(Side left, Side right) {
    if (left == Side::Yes && right == Side::Yes) return Sidewalk::Both;
    if (left == Side::Yes) return Sidewalk::Left;
    if (right == Side::Yes) return Sidewalk::Right;
    if (left == Side::Separate || right == Side::Separate) return Sidewalk::Separate;
    if (left == Side::No || right == Side::No) return Sidewalk::None;
    return Sidewalk::Unknown;
}

void readSidewalks(const TagLookup& tag, bool reversed, Road& r, std::map<std::string, uint64_t>& issues) {
    Side left = Side::Unknown, right = Side::Unknown;
    if (const char* value = tag("sidewalk")) {
        const Sidewalk s = parseSidewalk(value);
        const Side given = sideOf(value);
        left = s == Sidewalk::Right ? Side::No : given;
        right = s == Sidewalk::Left ? Side::No : given;
    }
    if (const char* both = tag("sidewalk:both")) left = right = sideOf(both);
    if (const char* value = tag("sidewalk:left")) left = sideOf(value);
    if (const char* value = tag("sidewalk:right")) right = sideOf(value);

    const auto widthOf = [&](const char* key, float& out) {
        const char* value = tag(key);
        if (!value) return;
        const std::optional<double> w = parseLength(value);
        if (w && *w > 0.0 && *w < kMaxSidewalkWidth) out = float(*w);
        else ++issues["road_bad_sidewalk_width_tag"];
    };
    float leftWidth = 0, rightWidth = 0, bothWidth = 0;
    widthOf("sidewalk:width", bothWidth);
    widthOf("sidewalk:both:width", bothWidth);
    leftWidth = rightWidth = bothWidth;
    widthOf("sidewalk:left:width", leftWidth);
    widthOf("sidewalk:right:width", rightWidth);
    // Left and right are seen along the way; a flipped centerline swaps them.
    if (reversed) {
        std::swap(left, right);
        std::swap(leftWidth, rightWidth);
    }
    r.sidewalk = combine(left, right);
    r.sidewalkLeftWidth = leftWidth;
    r.sidewalkRightWidth = rightWidth;
}

} // namespace

bool isCarriageway(HighwayClass highway) {
    switch (highway) {
    case HighwayClass::Motorway:
    case HighwayClass::Trunk:
    case HighwayClass::Primary:
    case HighwayClass::Secondary:
    case HighwayClass::Tertiary:
    case HighwayClass::Unclassified:
    case HighwayClass::Residential:
    case HighwayClass::Service:
    case HighwayClass::LivingStreet: return true;
    default: return false;
    }
}

Road roadFromTags(const TagLookup& tag, int64_t osmId, bool& reversed,
                  std::map<std::string, uint64_t>& issues) {
    Road r;
    r.osmId = osmId;
    const char* highway = tag("highway");
    r.highway = highway ? parseHighwayClass(highway) : HighwayClass::Other;

    const char* oneway = tag("oneway");
    reversed = is(oneway, "-1");
    r.oneway = reversed || (oneway && isYes(trim(oneway))) ||
               (!oneway && (r.highway == HighwayClass::Motorway || is(tag("junction"), "roundabout")));
    readLanesAndWidth(tag, reversed, r, issues);
    readSidewalks(tag, reversed, r, issues);

    if (const char* surface = tag("surface")) {
        r.surface = parseRoadSurface(surface);
        if (r.surface == RoadSurface::Unknown && isMalformedValue(surface)) ++issues["road_bad_surface_tag"];
    }
    const char* footway = tag("footway");
    r.footway = is(footway, "sidewalk") ? FootwayKind::Sidewalk
              : is(footway, "crossing") ? FootwayKind::Crossing
                                        : FootwayKind::None;
    r.laneMarkings = !is(tag("lane_markings"), "no");
    r.overtaking = !is(tag("overtaking"), "no") &&
                   !(is(tag("overtaking:forward"), "no") && is(tag("overtaking:backward"), "no"));
    const char* area = tag("area");
    r.area = area && isYes(trim(area));
    assignLevel(levelFromTags(tag, "road_bad_layer_tag", issues), r);
    return r;
}

std::optional<CrossingKind> crossingKindFromTags(const TagLookup& tag) {
    const char* crossing = tag("crossing");
    const char* markings = tag("crossing:markings");
    if (is(crossing, "no")) return std::nullopt;
    if (is(crossing, "zebra") || is(tag("crossing_ref"), "zebra") || is(markings, "zebra")) return CrossingKind::Zebra;
    if (is(crossing, "unmarked") || is(markings, "no")) return CrossingKind::Unmarked;
    if (is(crossing, "traffic_signals")) return CrossingKind::TrafficSignals;
    return CrossingKind::Marked;
}

} // namespace urbis
