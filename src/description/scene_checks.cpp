#include "description/scene_checks.h"

#include "astro/civil_time.h"

#include <charconv>
#include <cmath>

namespace urbis {

std::optional<WallTileSize> wallTileSizeOf(const std::string& text) {
    if (text == "whole") return WallTileSize{};
    WallTileSize size;
    const char* end = text.data() + text.size();
    auto [x, ec] = std::from_chars(text.data(), end, size.slots);
    if (ec != std::errc() || x == end || *x != 'x') return std::nullopt;
    auto [last, ec2] = std::from_chars(x + 1, end, size.floors);
    if (ec2 != std::errc() || last != end || size.slots < 1 || size.floors < 1 || size.slots > 0xffff || size.floors > 0xffff)
        return std::nullopt;
    return size;
}

std::optional<SceneProblem> firstSceneProblem(const SceneDescription& d) {
    const SourceDescription& s = d.source;
    if (s.bbox) {
        const std::array<double, 4>& b = *s.bbox;
        if (!(b[1] >= -90 && b[3] <= 90 && b[0] < b[2] && b[1] < b[3]))
            return SceneProblem{"source.bbox", "--bbox",
                                "need MINLON < MAXLON in [-180, 180] and MINLAT < MAXLAT in [-90, 90]"};
        if (s.osm.empty()) return SceneProblem{"source.bbox", "--bbox", "crops an OSM file and needs source.osm (--osm)"};
    }
    if (s.heightRange && !((*s.heightRange)[0] <= (*s.heightRange)[1]))
        return SceneProblem{"source.height_range", "--building-height-range", "need MIN <= MAX"};
    const CameraDescription& c = d.camera;
    if (c.position.has_value() != c.target.has_value())
        return SceneProblem{c.position ? "camera.target" : "camera.position", "--camera",
                            "a camera position needs a target and a target a position"};
    if (c.position && !(length(*c.target - *c.position) > 0.0f))
        return SceneProblem{"camera.target", "--camera", "position and target are the same point"};
    if (c.geo && c.position)
        return SceneProblem{"camera.geo", "--camera-geo", "excludes camera.position and camera.target (--camera)"};
    if (c.geo && s.osm.empty())
        return SceneProblem{"camera.geo", "--camera-geo", "needs a city imported from source.osm (--osm)"};
    std::string timeError;
    if (!d.astronomy.time.empty() && !parseIsoTime(d.astronomy.time, timeError))
        return SceneProblem{"astronomy.time", "--time", "'" + d.astronomy.time + "': " + timeError};
    if (d.astronomy.location && !(std::abs((*d.astronomy.location)[1]) <= 90.0))
        return SceneProblem{"astronomy.location", "--location", "latitude must be in [-90, 90] degrees"};
    if (!wallTileSizeOf(d.geometry.wallTiles))
        return SceneProblem{"geometry.wall_tiles", "--wall-tiles",
                            "need 'whole' or SLOTSxFLOORS (e.g. 4x4), got '" + d.geometry.wallTiles + "'"};
    if (d.planet && !d.animation.empty())
        return SceneProblem{"animation", "--planet", "animates the city only (planet.camera has no keyframes)"};
    for (size_t i = 0; i < d.animation.camera.size(); ++i) {
        const CameraKeyframe& k = d.animation.camera[i];
        const std::string key = "animation.camera[" + std::to_string(i) + "]";
        if (k.geo && s.osm.empty()) return SceneProblem{key + ".geo", "--osm", "needs a city imported from source.osm (--osm)"};
        if (!k.target && !k.heading && !c.target)
            return SceneProblem{key, "--camera", "needs a target, or heading and pitch (camera.target is unset)"};
    }
    if (d.planet && !(d.planet->amplitude < 0.2 * d.planet->radiusKm * 1e3))
        return SceneProblem{"planet.amplitude", "--planet", "must be under a fifth of the radius"};
    if (d.planet && !(std::fabs(d.planet->seaLevel) <= d.planet->amplitude + 1.0f))
        return SceneProblem{"planet.sea_level", "--planet", "must lie within the terrain's amplitude"};
    return std::nullopt;
}

} // namespace urbis
