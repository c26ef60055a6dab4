#include "streets/street_mesher.h"

#include "streets/ground_cover.h"

namespace urbis {

StreetMesh meshStreets(const CityModel& city, const StreetOptions& options) {
    StreetMesh out;
    meshGroundCover(city, options, out);
    return out;
}

} // namespace urbis
