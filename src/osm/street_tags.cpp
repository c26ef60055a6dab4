#include "osm/street_tags.h"

#include "osm/tag_parsing.h"

#include <array>
#include <optional>
#include <string_view>

namespace urbis {

namespace {

constexpr float kLaneWidth = 3.25f; // m

struct ClassDefaults {
    HighwayClass highway;
    float width; // m
    int lanes;
};
constexpr std::array<ClassDefaults, 16> kClassDefaults = {{
    {HighwayClass::Motorway, 11.0f, 3},   {HighwayClass::Trunk, 10.0f, 3},
    {HighwayClass::Primary, 9.0f, 2},     {HighwayClass::Secondary, 8.0f, 2},
    {HighwayClass::Tertiary, 7.0f, 2},    {HighwayClass::Unclassified, 6.0f, 2},
    {HighwayClass::Residential, 6.0f, 2}, {HighwayClass::Service, 4.0f, 1},
    {HighwayClass::LivingStreet, 5.0f, 1}, {HighwayClass::Pedestrian, 5.0f, 1},
    {HighwayClass::Footway, 2.0f, 1},     {HighwayClass::Cycleway, 2.0f, 1},
    {HighwayClass::Path, 1.5f, 1},        {HighwayClass::Steps, 2.0f, 1},
    {HighwayClass::Track, 3.0f, 1},       {HighwayClass::Other, 4.0f, 1}}};

ClassDefaults defaultsOf(HighwayClass highway) {
    for (const ClassDefaults& d : kClassDefaults)
        if (d.highway == highway) return d;
    return kClassDefaults.back();
}

bool isTrue(const char* value) { return value && std::string_view(value) != "no"; }

} // namespace

Road roadFromTags(const TagLookup& tag, int64_t osmId, bool& reversed,
                  std::map<std::string, uint64_t>& issues) {
    Road r;
    r.osmId = osmId;
    const char* highway = tag("highway");
    r.highway = highway ? parseHighwayClass(highway) : HighwayClass::Other;
    const ClassDefaults defaults = defaultsOf(r.highway);

    const char* oneway = tag("oneway");
    const char* junction = tag("junction");
    reversed = oneway && std::string_view(oneway) == "-1";
    r.oneway = reversed || (oneway && isYes(oneway)) ||
               (!oneway && (r.highway == HighwayClass::Motorway ||
                            (junction && std::string_view(junction) == "roundabout")));

    std::optional<int> lanes;
    if (const char* value = tag("lanes")) {
        lanes = parseInteger(value);
        if (!lanes || *lanes < 1 || *lanes > 16) {
            ++issues["road_bad_lanes_tag"];
            lanes.reset();
        }
    }
    r.lanes = lanes ? *lanes : (r.oneway ? 1 : defaults.lanes);
    r.width = lanes ? float(*lanes) * kLaneWidth : defaults.width;
    if (const char* value = tag("width")) {
        const std::optional<double> width = parseLength(value);
        if (width && *width > 0.0 && *width < 100.0) r.width = float(*width);
        else ++issues["road_bad_width_tag"];
    }

    const char* sidewalk = tag("sidewalk");
    if (!sidewalk) sidewalk = tag("sidewalk:both");
    r.sidewalk = sidewalk ? parseSidewalk(sidewalk) : Sidewalk::Unknown;
    if (const char* layer = tag("layer")) {
        const std::optional<int> value = parseInteger(layer);
        if (value) r.layer = *value;
        else ++issues["road_bad_layer_tag"];
    }
    r.bridge = isTrue(tag("bridge"));
    r.tunnel = isTrue(tag("tunnel"));
    return r;
}

Lamp lampFromTags(const TagLookup& tag, int64_t osmId) {
    Lamp lamp;
    lamp.osmId = osmId;
    const char* mount = tag("lamp_mount");
    const std::string_view mountKind = mount ? mount : "";
    if (mountKind == "wall" || mountKind == "wall_mounted") lamp.height = 4.5f;
    else if (mountKind == "suspended" || mountKind == "wire") lamp.height = 7.0f;
    if (const char* height = tag("height"))
        if (const std::optional<double> h = parseLength(height); h && *h > 0.5 && *h < 50.0)
            lamp.height = float(*h);
    const char* type = tag("lamp_type");
    if (!type) type = tag("light:method");
    if (type) lamp.lampType = type;
    if (const char* count = tag("light:count"))
        if (const std::optional<int> n = parseInteger(count); n && *n >= 1 && *n <= 16)
            lamp.lightCount = *n;
    if (const char* colour = tag("light:colour"))
        lamp.colourTemperature = parseColourTemperature(colour).value_or(0.0f);
    return lamp;
}

} // namespace urbis
