#include "prepare/scene_city.h"

#include "description/scene_parts.h"
#include "layout/city_layout.h"
#include "osm/osm_import.h"

namespace urbis {

namespace {

/// Scales every building's heights by the source's height scale.
void scaleHeights(CityModel& city, float scale) {
    if (scale == 1.0f) return;
    for (Building& b : city.buildings) {
        b.height *= scale;
        b.minHeight *= scale;
        b.roofHeight *= scale;
    }
}

} // namespace

CityModel loadSceneCity(const SceneDescription& d) {
    CityModel city = d.source.osm.empty() ? generateCity(layoutParamsOf(d.source))
                                          : importOsm(d.source.osm, importOptionsOf(d.source));
    applyColourOverrides(d.materials, city);
    scaleHeights(city, d.source.heightScale);
    return city;
}

CityMeshOptions cityMeshOptionsOf(const SceneDescription& d, size_t memoryLimit) {
    CityMeshOptions o;
    o.geometry = d.geometry.modes;
    o.materials = d.materials.city;
    o.memoryLimit = memoryLimit;
    o.streets = d.geometry.streets;
    o.traffic = choiceNamed(kTrafficSides, d.geometry.traffic).value_or(std::nullopt);
    o.hour = hourOf(d);
    o.water = d.water;
    o.trees = d.trees;
    return o;
}

} // namespace urbis
