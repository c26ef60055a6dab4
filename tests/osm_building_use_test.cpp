// buildingTypeFromTags: the building value first, then what a bare building=yes is used for.
#include "osm/building_use.h"

#include "tag_map.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

using namespace urbis;
using test::tagsOf;

TEST(BuildingUse, Table) {
    using T = BuildingType;
    const std::pair<std::map<std::string, std::string>, T> rows[] = {
        {{{"building", "apartments"}, {"shop", "bakery"}}, T::Apartments},   // the value wins
        {{{"building", "church"}}, T::Religious},
        {{{"building:part", "church"}}, T::Religious},
        {{{"building", "yes"}, {"amenity", "place_of_worship"}}, T::Religious}, // London's St Bride's
        {{{"building", "yes"}, {"historic", "church"}}, T::Religious},
        {{{"building", "yes"}, {"man_made", "tower"}, {"tower:type", "bell_tower"}}, T::Religious},
        {{{"building", "yes"}, {"amenity", "school"}}, T::School},
        {{{"building", "yes"}, {"amenity", "university"}}, T::School},
        {{{"building", "yes"}, {"amenity", "hospital"}}, T::Hospital},
        {{{"building", "yes"}, {"tourism", "hotel"}}, T::Hotel},
        {{{"building", "yes"}, {"tourism", "hostel"}}, T::Hotel},
        {{{"building", "yes"}, {"amenity", "townhall"}}, T::Civic},
        {{{"building", "yes"}, {"railway", "station"}}, T::Civic},
        {{{"building", "yes"}, {"office", "lawyer"}}, T::Office},
        {{{"building", "yes"}, {"office", "no"}}, T::Generic},
        {{{"building", "yes"}, {"shop", "newsagent"}}, T::Retail},
        {{{"building", "yes"}, {"shop", "clothes"}, {"amenity", "place_of_worship"}}, T::Religious}, // first row wins
        {{{"building", "yes"}, {"amenity", "parking"}}, T::Garage},
        {{{"building", "yes"}, {"industrial", "brewery"}}, T::Industrial},
        {{{"building", "yes"}, {"man_made", "works"}}, T::Industrial},
        {{{"building", "yes"}, {"amenity", "pub"}}, T::Generic},
        {{{"building", "yes"}, {"man_made", "tower"}}, T::Generic},
        {{{"building", "yes"}}, T::Generic},
        {{{"building", "spaceport"}, {"tourism", "hotel"}}, T::Hotel},      // unlisted value: use decides
        {{}, T::Generic},
    };
    for (const auto& [tags, type] : rows) {
        std::string text;
        for (const auto& [k, v] : tags) text += k + "=" + v + " ";
        EXPECT_EQ(buildingTypeFromTags(tagsOf(tags)), type) << text;
    }
}
