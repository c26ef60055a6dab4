#include "streets/street_mesher.h"

namespace urbis {

StreetMesh meshStreets(const CityModel& city, const StreetOptions& options) {
    StreetMesh out;
    (void)city;
    (void)options;
    return out;
}

} // namespace urbis
