#include "streets/street_mesher.h"

#include "streets/bridge_mesher.h"
#include "streets/ground_cover.h"
#include "streets/railway_mesher.h"
#include "streets/road_elevation.h"

namespace urbis {

StreetMesh meshStreets(const CityModel& city, const StreetOptions& options) {
    StreetMesh out;
    meshBridges(city.roads, roadElevations(city.roads), options, out);
    meshRailways(city, options, out);
    meshGroundCover(city, options, out);
    return out;
}

} // namespace urbis
