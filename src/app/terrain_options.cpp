// The terrain's command-line options, a part of SceneCommandLine (app/scene_options.h).
#include "app/scene_options.h"

#include <iterator>

namespace urbis {

void SceneCommandLine::addTerrainOptions(CLI::App& cmd) {
    SceneDescription& v = values_;
    auto add = [&](const char* name, std::string& storage, const char* help, auto apply) {
        if (!wanted(name)) return static_cast<CLI::Option*>(nullptr);
        CLI::Option* option = cmd.add_option(name, storage, help);
        overrides_.emplace_back(option, [&storage, apply](SceneDescription& d) { apply(d, storage); });
        return option;
    };
    if (CLI::Option* o = add("--terrain", v.terrain.kind,
                             "Terrain under the city: none (the flat ground) or fbm (a procedural landscape; with --dem, added to it)",
                             [](SceneDescription& d, const std::string& s) { d.terrain.kind = s; }))
        o->check(CLI::IsMember(std::vector<std::string>(std::begin(kTerrainKinds), std::end(kTerrainKinds))))->capture_default_str();
    add("--dem", v.terrain.dem,
        "Elevation raster GDAL opens (GeoTIFF, .vrt, any CRS): real terrain under the city, metres above sea level",
        [](SceneDescription& d, const std::string& s) { d.terrain.dem = s; });
    if (CLI::Option* o = add("--terrain-march", v.terrain.march,
                             "How rays find the terrain: hierarchy (min/max mips, exact), lei (the Cambridge dynamic step) or "
                             "reference (fixed small steps)",
                             [](SceneDescription& d, const std::string& s) { d.terrain.march = s; }))
        o->check(CLI::IsMember(std::vector<std::string>(std::begin(kTerrainMarches), std::end(kTerrainMarches))))
            ->capture_default_str();
}

} // namespace urbis
