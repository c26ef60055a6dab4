// facadeStyleOf: balconies only on buildings people live in, over many seeds, for OSM
// buildings and for the generated city.
#include "citygen/facade_style.h"
#include "layout/city_layout.h"

#include <gtest/gtest.h>

using namespace urbis;

namespace {

/// How many of 500 seeds give a building of `type` balconies.
int balconiedSeeds(BuildingType type) {
    Building b;
    b.type = type;
    b.height = 12.0f; // below curtain-wall height: every seed reaches the balcony draw
    int n = 0;
    for (uint32_t seed = 0; seed < 500; ++seed) {
        b.seed = seed * 2654435761u;
        n += facadeStyleOf(b).flags & kWallBalconies ? 1 : 0;
    }
    return n;
}

} // namespace

TEST(FacadeStyle, BalconiesOnlyWherePeopleLive) {
    using T = BuildingType;
    for (T type : {T::Generic, T::Commercial, T::Retail, T::Office, T::Industrial, T::Warehouse, T::Religious,
                   T::Civic, T::School, T::Hospital, T::Garage, T::Shed, T::Roof})
        EXPECT_EQ(balconiedSeeds(type), 0) << int(type);
    for (T type : {T::Residential, T::Apartments, T::Hotel}) {
        EXPECT_GT(balconiedSeeds(type), 100) << int(type);
        EXPECT_LT(balconiedSeeds(type), 400) << int(type); // some, not all
    }
    EXPECT_GT(balconiedSeeds(T::House), 0);
}

TEST(FacadeStyle, GeneratedCityHasBalconiesOnItsHomesOnly) {
    LayoutParams params;
    params.buildings = 400;
    const CityModel city = generateCity(params);
    int homes = 0, others = 0;
    for (const Building& b : city.buildings) {
        if (!(facadeStyleOf(b).flags & kWallBalconies)) continue;
        const bool home = b.type == BuildingType::Residential || b.type == BuildingType::Apartments ||
                          b.type == BuildingType::House || b.type == BuildingType::Hotel;
        ++(home ? homes : others);
    }
    EXPECT_GT(homes, 20);
    EXPECT_EQ(others, 0);
}
