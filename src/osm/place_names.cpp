#include "osm/place_names.h"

#include "base/input_error.h"

#include <osmium/handler.hpp>
#include <osmium/handler/node_locations_for_ways.hpp>
#include <osmium/index/map/flex_mem.hpp>
#include <osmium/io/any_input.hpp>
#include <osmium/visitor.hpp>

namespace urbis {

namespace {

/// Collects named nodes and ways (node locations already set on the ways).
class NameCollector : public osmium::handler::Handler {
public:
    explicit NameCollector(std::vector<NamedPlace>& out) : out_(out) {}

    void node(const osmium::Node& node) {
        const char* name = node.tags().get_value_by_key("name");
        if (name && *name && node.location().valid()) out_.push_back({name, node.location().lon(), node.location().lat()});
    }

    void way(const osmium::Way& way) {
        const char* name = way.tags().get_value_by_key("name");
        if (!name || !*name) return;
        double lon = 0, lat = 0;
        size_t located = 0;
        // A closed way repeats its first node: counted once.
        const size_t count = way.nodes().size() - (way.nodes().size() > 1 && way.is_closed() ? 1 : 0);
        for (size_t i = 0; i < count; ++i) {
            const osmium::Location location = way.nodes()[i].location();
            if (!location.valid()) continue;
            lon += location.lon();
            lat += location.lat();
            ++located;
        }
        if (located) out_.push_back({name, lon / double(located), lat / double(located)});
    }

private:
    std::vector<NamedPlace>& out_;
};

} // namespace

std::vector<NamedPlace> readPlaceNames(const std::string& path) {
    std::vector<NamedPlace> places;
    try {
        using Index = osmium::index::map::FlexMem<osmium::unsigned_object_id_type, osmium::Location>;
        Index index;
        osmium::handler::NodeLocationsForWays<Index> locations{index};
        locations.ignore_errors();   // a way's missing nodes are left out of its centre
        NameCollector collector{places};
        osmium::io::Reader reader{osmium::io::File{path}, osmium::osm_entity_bits::node | osmium::osm_entity_bits::way,
                                  osmium::io::read_meta::no};
        osmium::apply(reader, locations, collector);
        reader.close();
    } catch (const std::exception& e) {
        throw InputError(path + ": cannot read the names of its features: " + e.what());
    }
    return places;
}

} // namespace urbis
