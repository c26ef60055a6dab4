// Objects counted by reason (dropped, repaired), with the OSM ids of those that have one.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace urbis {

enum class OsmType : uint8_t { Node, Way, Relation };

/// An OSM object: its type and its (positive) id.
struct OsmRef {
    OsmType type = OsmType::Way;
    int64_t id = 0;
};

/// The ref of a Building::osmId or Area::osmId: ways positive, relations negative.
inline OsmRef polygonRef(int64_t osmId) {
    return osmId < 0 ? OsmRef{OsmType::Relation, -osmId} : OsmRef{OsmType::Way, osmId};
}

/// "n123", "w123" or "r456", as osmium names objects.
std::string osmRefName(OsmRef ref);

/// The objects counted under one reason.
struct ReasonEntry {
    uint64_t count = 0;
    std::vector<OsmRef> ids;  ///< of the counted objects that have one, in the order counted
};

/// Reason ("outside_bbox", "bad_height_tag", ...; docs/cli.md lists them) -> its objects.
/// Any string is a reason: new ones need no change here, only a line in docs/cli.md.
using ReasonLog = std::map<std::string, ReasonEntry>;

/// Counts `n` problems of one object under `reason` and lists its id once.
void record(ReasonLog& log, const std::string& reason, OsmRef id, uint64_t n = 1);

/// Counts `n` objects under `reason` that have no id to list.
void recordCount(ReasonLog& log, const std::string& reason, uint64_t n);

/// How many were counted under `reason` (0 if none).
uint64_t countOf(const ReasonLog& log, const std::string& reason);

} // namespace urbis
