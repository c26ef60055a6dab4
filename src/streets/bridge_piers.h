// Piers under decks: columns from the ground to the underside every kPierSpacing metres along a chain
// of bridge ways, where the deck is high enough, kept off the ways that pass underneath.
#pragma once

#include "model/city_model.h"
#include "scene/triangle_mesh.h"
#include "streets/bridge_segment_grid.h"

#include <cstdint>
#include <vector>

namespace urbis {

/// Distance between piers along a deck, m; and the least clearance under the deck for a pier.
inline constexpr double kPierSpacing = 30.0;
inline constexpr float kPierMinClearance = 2.5f;

/// The level of ways on the ground among PierObstacles' levels (bridges have their layer).
inline constexpr int kGroundLevel = -1000;

/// Where piers may not stand: the ways under a deck in plan (their centerlines widened by half their
/// width) at their level (kGroundLevel, or a bridge's layer).
class PierObstacles {
public:
    void add(const std::vector<Vec2d>& line, double halfWidth, int level) { grid_.add(line, halfWidth + 1.0, 0, level); }
    /// Whether a column of `radius` metres (at most 1 m) at `p` would stand on, or pass through, a
    /// way of a level below `level`.
    bool blocks(Vec2d p, double radius, int level) const;

private:
    SegmentGrid grid_;
};

/// Per line: metres along its chain of consecutive lines (one's end point equal to the next's start)
/// where it starts, so that pier stations run on across a viaduct mapped as many ways. Deterministic:
/// chains start at lines whose start no other line ends at, in index order.
std::vector<double> chainOffsets(const std::vector<const std::vector<Vec2d>*>& lines);

/// A deck's cross-section as piers see it.
struct PierDeck {
    double chainStart = 0;                 ///< chainOffsets of the line
    double leftWidth = 0, rightWidth = 0;  ///< m from the centerline to the deck's edges
    float underside = 0;                   ///< m of the underside above the elevation
    int level = 0;                         ///< the deck's layer: piers keep off the ways below it
};

/// Meshes square columns under `line` at elevation (m per point) where its chain distance is a
/// multiple of kPierSpacing plus half of it (moved up to 8 m along to keep off `obstacles`, else left
/// out), one column per ~10 m of deck width, where the underside is kPierMinClearance above the ground.
/// Returns the triangles added.
size_t meshPiers(const std::vector<Vec2d>& line, const std::vector<float>& elevation, const PierDeck& deck,
                 const PierObstacles& obstacles, TriangleInfo info, TriangleMesh& mesh);

} // namespace urbis
