#include "streets/street_mesher.h"

#include "streets/bridge_mesher.h"
#include "streets/ground_cover.h"
#include "streets/lamp_placement.h"
#include "streets/railway_mesher.h"
#include "streets/road_elevation.h"
#include "streets/road_fitting.h"
#include "streets/street_lamps.h"
#include "streets/street_network.h"

namespace urbis {

StreetMesh meshStreets(const CityModel& city, const StreetOptions& options) {
    StreetMesh out;
    // The roads first: their object ids are firstObject + the fitted road's index, which the
    // bridges' structure shares; the other parts take theirs after out.objects.
    const std::vector<Road> fitted = fitRoads(city, out.dropped);
    const std::vector<std::vector<float>> elevations = roadElevations(fitted);
    meshStreetNetwork(city, fitted, elevations, options, out);
    meshBridges(fitted, elevations, options, out);
    meshRailways(city, options, out);
    meshGroundCover(city, options, out);
    addLamps(streetLamps(city, fitted), options, out);
    return out;
}

} // namespace urbis
