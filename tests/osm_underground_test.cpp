// isUnderground: which buildings and parts lie wholly below ground, from their tags alone.
// Rows are tag sets seen in real extracts (San Francisco's metro stations, London's basement
// shops, Berlin's underground garages, Moscow's indoor substations) and the edge cases of
// each rule.
#include "osm/underground_tags.h"

#include "tag_map.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

using namespace urbis;
using test::tagsOf;

namespace {

struct Row {
    std::map<std::string, std::string> tags;
    bool underground;
};

const Row kRows[] = {
    // location
    {{{"building", "train_station"}, {"location", "underground"}}, true},
    {{{"building", "bunker"}, {"location", "underground"}}, true},
    {{{"building:part", "yes"}, {"location", "underground;indoor"}}, true},
    {{{"building", "service"}, {"location", "indoor"}}, false},  // a substation inside a building
    {{{"building", "yes"}, {"location", "surface"}, {"level", "-1"}}, false}, // explicit wins
    {{{"building", "yes"}, {"location", "roof"}}, false},
    {{{"building", "yes"}, {"location", "underground;surface"}}, false},
    {{{"building", "bunker"}}, false},  // a bunker above ground (flak towers, pillboxes)
    // layer alone: vertical order of crossing features, not depth
    {{{"building", "yes"}, {"layer", "-1"}, {"building:levels", "2"}}, false},
    {{{"building", "transportation"}, {"layer", "-1"}, {"min_level", "-2"}, {"max_level", "5"}, {"height", "30"}}, false},
    {{{"building", "yes"}, {"layer", "-1"}, {"location", "indoor"}}, false},
    {{{"building:part", "yes"}, {"layer", "-2"}}, false},
    // tunnel
    {{{"building", "yes"}, {"tunnel", "yes"}}, true},
    {{{"building", "yes"}, {"tunnel", "culvert"}}, true},
    {{{"building", "yes"}, {"tunnel", "no"}}, false},
    {{{"building", "yes"}, {"tunnel", "building_passage"}}, false},
    {{{"building", "roof"}, {"tunnel", "avalanche_protector"}}, false},
    // level / building:level
    {{{"building:part", "garages"}, {"level", "-1"}}, true},
    {{{"building:part", "yes"}, {"level", "-2;-1"}}, true},
    {{{"building", "train_station"}, {"level", "-3;-2;-1"}}, true},
    {{{"building:part", "yes"}, {"level", "-1--3"}}, true},
    {{{"building", "yes"}, {"level", "-0.9"}}, true},
    {{{"building", "yes"}, {"building:level", "-1"}}, true},
    {{{"building", "yes"}, {"level", " -1 ; -2 "}}, true},
    {{{"building", "yes"}, {"level", "-1;0;1"}}, false},
    {{{"building:part", "elevator"}, {"level", "-2;0"}}, false},
    {{{"building", "elevator"}, {"level", "-1;-0.9;0"}}, false},
    {{{"building:part", "yes"}, {"level", "-1-2"}}, false},  // a range from -1 up to 2
    {{{"building", "yes"}, {"level", "0"}}, false},
    {{{"building:part", "yes"}, {"level", "1-5"}}, false},
    {{{"building", "yes"}, {"level", "basement"}}, false},   // unparsable: no evidence
    {{{"building", "yes"}, {"level", ""}}, false},
    // max_level / min_level
    {{{"building", "train_station"}, {"min_level", "-3"}, {"max_level", "-1"}}, true},
    {{{"building:part", "yes"}, {"building:max_level", "-2"}}, true},
    {{{"building:part", "yes"}, {"max_level", "0"}}, false},
    {{{"building:part", "yes"}, {"min_level", "-3"}}, false},
    {{{"building:part", "yes"}, {"building:min_level", "-1"}, {"building:levels", "4"}}, false},
    {{{"building:part", "yes"}, {"min_level", "3"}, {"max_level", "4"}}, false},  // a bridge
    {{{"building:part", "yes"}, {"building:min_level", "3"}}, false},
    // building:levels:underground
    {{{"building", "yes"}, {"building:levels", "0"}, {"building:levels:underground", "2"}}, true},
    {{{"building", "yes"}, {"building:levels", "3"}, {"building:levels:underground", "2"}}, false},
    {{{"building", "yes"}, {"building:levels:underground", "2"}}, false},
    {{{"building", "yes"}, {"building:levels", "0"}, {"building:levels:underground", "0"}}, false},
    // building=underground
    {{{"building", "underground"}}, true},
    {{{"building:part", "underground"}}, true},
    // parking
    {{{"building", "yes"}, {"amenity", "parking"}, {"parking", "underground"}, {"layer", "-1"}}, true},
    {{{"building", "garages"}, {"parking", "underground"}}, true},
    {{{"building", "parking"}, {"parking", "underground"}}, true},
    {{{"building", "apartments"}, {"parking", "underground"}}, false},  // the flats' car park
    {{{"building", "yes"}, {"amenity", "parking"}, {"parking", "multi-storey"}}, false},
    // nothing said
    {{{"building", "yes"}}, false},
    {{{"building", "yes"}, {"min_height", "20"}}, false},
};

} // namespace

TEST(UndergroundTags, Table) {
    for (const Row& row : kRows) {
        std::string text;
        for (const auto& [k, v] : row.tags) text += k + "=" + v + " ";
        EXPECT_EQ(isUnderground(tagsOf(row.tags)), row.underground) << text;
    }
}
