#include "streets/street_mesher.h"

#include "streets/road_fitting.h"
#include "streets/street_network.h"

namespace urbis {

StreetMesh meshStreets(const CityModel& city, const StreetOptions& options) {
    StreetMesh out;
    const std::vector<Road> fitted = fitRoads(city, out.dropped);
    meshStreetNetwork(city, fitted, std::vector<std::vector<float>>(fitted.size()), options, out);
    return out;
}

} // namespace urbis
