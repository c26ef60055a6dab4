// The street network of a generated city: a grid of avenues and streets whose spacing is
// perturbed per line, crossed by a few arterials (diagonals through the centre and a ring).
#pragma once

#include "layout/layout_geometry.h"
#include "layout/street_profile.h"
#include "model/city_model.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace urbis {

class River;

/// One straight grid line (a street running the whole grid) at a fixed x or y, in metres: the main
/// axes are 6-lane primaries, every 4th (north-south) or 3rd (east-west) line an avenue of 2 or 4
/// lanes, the others residential, a quarter of them one-way with 1 or 2 lanes.
struct GridLine {
    double position = 0;   ///< m, x of a north-south line or y of an east-west line
    StreetProfile profile;
    bool reversed = false; ///< a one-way street whose traffic runs south or west
    /// Distance in metres from the centerline to the far edge of the sidewalk.
    double halfCorridor() const { return profile.halfCorridor(); }
};

/// Whether segment `segment` of grid line `line` is a street: on a north-south line it runs from
/// east-west line `segment` to the next, on an east-west line from north-south line `segment`.
using GridSegmentFilter = std::function<bool(bool northSouth, int line, int segment)>;

/// A seeded grid of `2 * half` x `2 * half` blocks around (0, 0). Line k of either axis
/// (k in [-half, half]) depends only on the seed and k, so a larger grid extends a smaller one.
class StreetGrid {
public:
    /// Builds the lines for blocks i, j in [-half, half).
    StreetGrid(uint32_t seed, int half);
    int half() const { return half_; }
    /// North-south line k (constant x), k in [-half, half].
    const GridLine& xLine(int k) const { return xLines_[static_cast<size_t>(k + half_)]; }
    /// East-west line k (constant y), k in [-half, half].
    const GridLine& yLine(int k) const { return yLines_[static_cast<size_t>(k + half_)]; }
    /// Buildable rectangle of block (i, j) in metres: between lines i, i+1 (x) and j, j+1 (y),
    /// inside the sidewalks.
    Rect2d blockInterior(int i, int j) const;
    /// Whether p (metres) lies on a north-south grid road or its sidewalks.
    bool onNorthSouthRoad(Vec2d p) const;
    /// Whether p (metres) lies on an east-west grid road or its sidewalks.
    bool onEastWestRoad(Vec2d p) const;
    /// Grid roads bordering the blocks marked in `used` (index (j + half) * 2 * half + i + half) where
    /// `keep` says so, one Road per maximal run of segments along a line, with a vertex at every crossing.
    std::vector<Road> roads(const std::vector<bool>& used, const GridSegmentFilter& keep) const;

private:
    int half_;
    std::vector<GridLine> xLines_, yLines_;
};

/// Arterials laid over the grid: straight diagonals through the centre and an optional ring.
struct Arterials {
    std::vector<Vec2d> diagonals;  ///< unit directions of straight roads through (0, 0)
    double ringRadius = 0;  ///< m around (0, 0); 0 when there is no ring
    StreetProfile diagonal = streetProfile(HighwayClass::Primary, 6);
    StreetProfile ring = streetProfile(HighwayClass::Primary, 4);

    /// Seeded arterials for a city of about `cityRadius` metres; fewer (or none) for small cities.
    /// The ring meets the diagonals away from `river`, so that no junction is on a bridge.
    static Arterials generate(uint32_t seed, double cityRadius, const River& river);
    /// Whether rectangle r (metres) comes within the road or sidewalks of an arterial.
    bool blocks(const Rect2d& r) const;
    /// How many arterial roads (with their sidewalks) cover p (metres).
    int corridorsAt(Vec2d p) const;
    /// The arterials as roads clipped to the disc of radius `cityRadius` metres around (0, 0): the
    /// diagonals in order, then the ring.
    std::vector<Road> roads(double cityRadius) const;
};

} // namespace urbis
