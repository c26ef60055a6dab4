#include "streets/road_fitting.h"

#include "model/cell_grid.h"
#include "model/polygon_ops.h"
#include "streets/at_surface.h"
#include "streets/street_network_plane.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace urbis {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
/// Centerlines are tested against footprints in pieces of about this length (m): the resolution of a cut.
constexpr double kPieceLength = 1.0;
constexpr int kMaxPiecesPerSegment = 4096;
/// Kept between a corridor's edge and a footprint (m), so that rounding never makes them overlap.
constexpr double kBuildingMargin = 0.05;
/// The narrowest carriageway and path a squeeze may leave (m); below it the piece is cut out.
constexpr double kMinCarriageway = 2.5, kMinPath = 1.0;
/// A sidewalk narrower than this (m) after the squeeze is left out.
constexpr double kMinSidewalk = 0.75;
/// A road is in town (gets sidewalks by class) when a building lies this close (m).
constexpr double kTownRadius = 40.0;
/// A mapped sidewalk alongside: parallel within this cosine, at most this far beyond the carriageway (m),
/// over at least this share of the road's length.
constexpr double kParallelCosine = 0.8, kSidewalkReach = 10.0, kSidewalkShare = 0.3;
/// Buildings whose walls start this high (m) bridge the street (a passage): the street runs under them.
constexpr double kPassageHeight = 2.5;
/// Coordinates beyond this (m) are bad input.
constexpr double kHugeCoordinate = 1.0e7;

/// Defaults by class for an untagged `sidewalk` in town: both sides on streets with houses along them.
bool sidewalksByClass(HighwayClass h) {
    switch (h) {
    case HighwayClass::Primary:
    case HighwayClass::Secondary:
    case HighwayClass::Tertiary:
    case HighwayClass::Unclassified:
    case HighwayClass::Residential:
    case HighwayClass::LivingStreet: return true;
    default: return false;
    }
}

/// The footprints a street must keep clear of, filed in a grid.
struct Footprints {
    const std::vector<Building>& buildings;
    CellGrid grid{50.0};

    explicit Footprints(const std::vector<Building>& all) : buildings(all) {
        for (uint32_t i = 0; i < all.size(); ++i) {
            const Building& b = all[i];
            if (b.minHeight > kPassageHeight || b.footprint.outer.size() < 3) continue;
            std::array<Vec2d, 2> box{Vec2d{kInfinity, kInfinity}, Vec2d{-kInfinity, -kInfinity}};
            for (const Vec2d& p : b.footprint.outer) {
                box[0] = {std::min(box[0].x, p.x), std::min(box[0].y, p.y)};
                box[1] = {std::max(box[1].x, p.x), std::max(box[1].y, p.y)};
            }
            if (!(box[1].x - box[0].x < kHugeCoordinate && box[1].y - box[0].y < kHugeCoordinate)) continue;
            grid.insert(i, box);
        }
    }

    /// The distinct buildings whose cells a box around a and b, grown by `reach`, touches (ascending).
    std::vector<uint32_t> near(Vec2d a, Vec2d b, double reach) const {
        std::vector<uint32_t> found;
        grid.query({Vec2d{std::min(a.x, b.x) - reach, std::min(a.y, b.y) - reach},
                    Vec2d{std::max(a.x, b.x) + reach, std::max(a.y, b.y) + reach}},
                   [&](uint32_t i) { found.push_back(i); });
        std::sort(found.begin(), found.end());
        found.erase(std::unique(found.begin(), found.end()), found.end());
        return found;
    }

    template <typename F>
    void forEachEdge(uint32_t building, F&& f) const {
        const Polygon& poly = buildings[building].footprint;
        const auto ring = [&](const Ring& r) {
            for (size_t i = 0; i < r.size(); ++i) f(r[i], r[(i + 1) % r.size()]);
        };
        ring(poly.outer);
        for (const Ring& hole : poly.holes) ring(hole);
    }
};

/// How far a centerline piece's corridor may reach to each side before it meets a footprint, and
/// whether the piece lies in (or runs into) one.
struct PieceClearance {
    double left = kInfinity, right = kInfinity;
    bool blocked = false;
};

/// Clearances of the pieces of segment a -> b (equal lengths): a footprint edge clipped to a piece's
/// strip limits the side it lies on; one that crosses the centerline, or an inside interval (even-odd
/// over all rings along the centerline's line), blocks the piece.
void clearSegment(const Footprints& footprints, Vec2d a, Vec2d b, double reach, std::vector<PieceClearance>& pieces) {
    const double segment = length(b - a);
    const Vec2d d = (b - a) * (1.0 / segment), n = perpLeft(d);
    const double step = segment / double(pieces.size());
    const auto pieceOf = [&](double u) {
        return size_t(std::clamp(std::floor(u / step), 0.0, double(pieces.size() - 1)));
    };
    for (uint32_t building : footprints.near(a, b, reach)) {
        bool insideAtStart = false;
        std::vector<double> crossings;
        footprints.forEachEdge(building, [&](Vec2d p, Vec2d q) {
            const double up = dot(p - a, d), vp = dot(p - a, n), uq = dot(q - a, d), vq = dot(q - a, n);
            if ((vp > 0) != (vq > 0)) {
                const double u = up + (uq - up) * vp / (vp - vq);
                if (u < 0) insideAtStart = !insideAtStart;
                else if (u <= segment) crossings.push_back(u);
            }
            if ((up < 0 && uq < 0) || (up > segment && uq > segment)) return;
            if ((vp > reach && vq > reach) || (vp < -reach && vq < -reach)) return;
            const double du = uq - up;
            const auto vAt = [&](double u) { return du == 0 ? std::min(vp, vq) : vp + (vq - vp) * (u - up) / du; };
            const double lo = std::max(0.0, std::min(up, uq)), hi = std::min(segment, std::max(up, uq));
            for (size_t k = pieceOf(lo); k <= pieceOf(hi); ++k) {
                const double u0 = std::max(lo, double(k) * step), u1 = std::min(hi, double(k + 1) * step);
                if (u0 > u1) continue;
                const double v0 = du == 0 ? vp : vAt(u0), v1 = du == 0 ? vq : vAt(u1);
                PieceClearance& c = pieces[k];
                if (v0 * v1 <= 0) c.blocked = true;
                else if (v0 > 0) c.left = std::min(c.left, std::min(v0, v1));
                else c.right = std::min(c.right, std::min(-v0, -v1));
            }
        });
        std::sort(crossings.begin(), crossings.end());
        double from = 0;
        bool inside = insideAtStart;
        crossings.push_back(segment);
        for (double u : crossings) {
            if (inside)
                for (size_t k = pieceOf(from); k <= pieceOf(u); ++k) pieces[k].blocked = true;
            inside = !inside;
            from = u;
        }
    }
}

/// The shortest distance from p to a footprint within `reach`.
double distanceToFootprints(const Footprints& footprints, Vec2d p, double reach) {
    double best = kInfinity;
    for (uint32_t building : footprints.near(p, p, reach))
        footprints.forEachEdge(building, [&](Vec2d a, Vec2d b) { best = std::min(best, distanceToSegment(p, a, b)); });
    return best;
}

/// A piece of a way kept clear of buildings, with each segment's clearance to the left and right.
struct Run {
    uint32_t road = 0;
    std::vector<Vec2d> points;
    std::vector<double> left, right;   ///< per segment
};

/// The widest corridor half (carriageway half + sidewalk) a road may want, metres.
double reachOf(const Road& r) {
    const double sidewalk = std::max({double(r.sidewalkLeftWidth), double(r.sidewalkRightWidth),
                                      double(defaultSidewalkWidth(r.highway))});
    return r.width * 0.5 + sidewalk + 1.0;
}

double minHalfWidth(const Road& r) { return std::min(double(r.width), isPath(r.highway) ? kMinPath : kMinCarriageway) * 0.5; }

/// Cuts one way where its pieces are blocked or too squeezed for the narrowest carriageway; the
/// mitre of each kept bend is kept clear too (its outer corner reaches 1 / cos(half the turn) further).
void cutAtBuildings(const Footprints& footprints, const std::vector<Vec2d>& line, uint32_t road, const Road& r,
                    std::vector<Run>& runs, uint64_t& cutPieces) {
    const double reach = reachOf(r), minHalf = minHalfWidth(r);
    Run run;
    run.road = road;
    bool lastBlocked = false;
    const auto close = [&]() {
        if (run.points.size() >= 2) runs.push_back(run);
        run.points.clear();
        run.left.clear();
        run.right.clear();
    };
    std::vector<PieceClearance> pieces;
    for (size_t i = 0; i + 1 < line.size(); ++i) {
        const Vec2d a = line[i], b = line[i + 1];
        const double segment = length(b - a);
        pieces.assign(size_t(std::clamp(std::ceil(segment / kPieceLength), 1.0, double(kMaxPiecesPerSegment))), {});
        clearSegment(footprints, a, b, reach, pieces);
        // A bend at a that the run turns through: its mitre's outer corner must clear the footprints too.
        double mitreLeft = kInfinity, mitreRight = kInfinity;
        if (!run.points.empty() && !pieces[0].blocked) {
            const Vec2d before = a - line[i - 1];
            const double cosine = dot(before, b - a) / (length(before) * segment);
            const double scale = std::min(1.0 / std::max(std::sqrt(std::max(0.0, (1.0 + cosine) * 0.5)), 1e-9), 4.0);
            const double clear = distanceToFootprints(footprints, a, reach * scale) / scale - kBuildingMargin;
            (cross(before, b - a) > 0 ? mitreRight : mitreLeft) = clear;
            run.left.back() = std::min(run.left.back(), mitreLeft);
            run.right.back() = std::min(run.right.back(), mitreRight);
        }
        for (size_t k = 0; k < pieces.size(); ++k) {
            const PieceClearance& c = pieces[k];
            const Vec2d from = k == 0 ? a : a + (b - a) * (double(k) / double(pieces.size()));
            const bool blocked = c.blocked || std::min(c.left, c.right) - kBuildingMargin < minHalf;
            if (blocked) {
                if (!lastBlocked) ++cutPieces;
                lastBlocked = true;
                if (!run.points.empty() && run.left.size() == run.points.size()) run.points.push_back(from);
                close();
                continue;
            }
            lastBlocked = false;
            if (run.points.empty()) run.points.push_back(from);
            if (run.left.size() + 1 == run.points.size()) {
                run.left.push_back(mitreLeft);
                run.right.push_back(mitreRight);
            }
            run.left.back() = std::min(run.left.back(), c.left - kBuildingMargin);
            run.right.back() = std::min(run.right.back(), c.right - kBuildingMargin);
            mitreLeft = mitreRight = kInfinity;
        }
        if (!run.points.empty()) run.points.push_back(b);
    }
    close();
}

/// The centerline without repeated points; empty when a coordinate is not finite or huge.
std::vector<Vec2d> cleanLine(const std::vector<Vec2d>& line) {
    std::vector<Vec2d> out;
    for (const Vec2d& p : line) {
        if (!(std::fabs(p.x) < kHugeCoordinate && std::fabs(p.y) < kHugeCoordinate)) return {};
        if (out.empty() || !(PointKey(out.back()) == PointKey(p))) out.push_back(p);
    }
    return out;
}

/// Separately mapped sidewalks (`footway=sidewalk`), segment by segment in a grid.
struct MappedSidewalks {
    std::vector<std::array<Vec2d, 2>> segments;
    CellGrid grid{25.0};

    explicit MappedSidewalks(const std::vector<Road>& roads) {
        for (const Road& r : roads) {
            if (r.footway != FootwayKind::Sidewalk || !atSurface(r)) continue;
            for (size_t i = 0; i + 1 < r.centerline.size(); ++i) {
                const Vec2d a = r.centerline[i], b = r.centerline[i + 1];
                if (!(std::fabs(a.x) + std::fabs(a.y) + std::fabs(b.x) + std::fabs(b.y) < kHugeCoordinate)) continue;
                grid.insert(uint32_t(segments.size()), {Vec2d{std::min(a.x, b.x), std::min(a.y, b.y)},
                                                        Vec2d{std::max(a.x, b.x), std::max(a.y, b.y)}});
                segments.push_back({a, b});
            }
        }
    }

    /// Whether mapped sidewalks run along `line` on its left / right over kSidewalkShare of its length,
    /// within kSidewalkReach beyond a carriageway of half width `half`.
    void alongside(const std::vector<Vec2d>& line, double half, bool& left, bool& right) const {
        double total = 0, onLeft = 0, onRight = 0;
        const double reach = half + kSidewalkReach;
        for (size_t i = 0; i + 1 < line.size(); ++i) {
            const Vec2d a = line[i], b = line[i + 1], m = (a + b) * 0.5;
            const double segment = length(b - a);
            const Vec2d d = (b - a) * (1.0 / segment);
            total += segment;
            bool l = false, r = false;
            grid.query({m - Vec2d{reach, reach}, m + Vec2d{reach, reach}}, [&](uint32_t s) {
                const Vec2d p = segments[s][0], q = segments[s][1], pq = q - p;
                const double l2 = dot(pq, pq);
                if (!(l2 > 0) || std::fabs(dot(pq, d)) < kParallelCosine * std::sqrt(l2)) return;
                const Vec2d closest = p + pq * std::clamp(dot(m - p, pq) / l2, 0.0, 1.0);
                if (length(closest - m) > reach) return;
                (cross(d, closest - m) > 0 ? l : r) = true;
            });
            onLeft += l ? segment : 0;
            onRight += r ? segment : 0;
        }
        left = onLeft > kSidewalkShare * total;
        right = onRight > kSidewalkShare * total;
    }
};

/// Whether a building lies within kTownRadius of the line.
bool inTown(const Footprints& footprints, const std::vector<Vec2d>& line) {
    Vec2d lo{kInfinity, kInfinity}, hi{-kInfinity, -kInfinity};
    for (const Vec2d& p : line) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    return !footprints.near(lo, hi, kTownRadius).empty();
}

/// Resolves the sidewalks of one edge and fits its corridor into the clearances (m from the
/// centerline to the nearest footprint, each side): sidewalks give way first, then the carriageway.
void fitWidths(Road& edge, const Footprints& footprints, const MappedSidewalks& mapped, double clearLeft,
               double clearRight) {
    bool left = false, right = false;
    if (!isPath(edge.highway)) {
        switch (edge.sidewalk) {
        case Sidewalk::Both: left = right = true; break;
        case Sidewalk::Left: left = true; break;
        case Sidewalk::Right: right = true; break;
        case Sidewalk::Unknown:
            if (sidewalksByClass(edge.highway) && inTown(footprints, edge.centerline)) {
                bool mappedLeft = false, mappedRight = false;
                mapped.alongside(edge.centerline, edge.width * 0.5, mappedLeft, mappedRight);
                left = !mappedLeft;
                right = !mappedRight;
            }
            break;
        default: break;
        }
    }
    const double wanted = edge.width * 0.5, fallback = defaultSidewalkWidth(edge.highway);
    const double half = std::max(minHalfWidth(edge), std::min({wanted, clearLeft, clearRight}));
    const auto sidewalkWidth = [&](bool has, float tagged, double clear) {
        const double width = std::min(has ? (tagged > 0 ? double(tagged) : fallback) : 0.0, clear - half);
        return width >= kMinSidewalk ? float(width) : 0.0f;
    };
    edge.width = float(2.0 * half);
    edge.sidewalkLeftWidth = sidewalkWidth(left, edge.sidewalkLeftWidth, clearLeft);
    edge.sidewalkRightWidth = sidewalkWidth(right, edge.sidewalkRightWidth, clearRight);
    const bool l = edge.sidewalkLeftWidth > 0, r = edge.sidewalkRightWidth > 0;
    edge.sidewalk = l && r ? Sidewalk::Both : l ? Sidewalk::Left : r ? Sidewalk::Right : Sidewalk::None;
}

} // namespace

bool isPath(HighwayClass highway) {
    return highway == HighwayClass::Footway || highway == HighwayClass::Cycleway || highway == HighwayClass::Path ||
           highway == HighwayClass::Steps;
}

float defaultSidewalkWidth(HighwayClass highway) {
    switch (highway) {
    case HighwayClass::Primary:
    case HighwayClass::Secondary: return 3.0f;
    case HighwayClass::Tertiary: return 2.5f;
    case HighwayClass::LivingStreet: return 1.5f;
    default: return 2.0f;
    }
}

std::vector<Road> fitRoads(const CityModel& city, std::map<std::string, uint64_t>& dropped) {
    const Footprints footprints(city.buildings);
    std::vector<Run> runs;
    uint64_t cut = 0;
    for (uint32_t i = 0; i < city.roads.size(); ++i) {
        const Road& r = city.roads[i];
        if (!atSurface(r)) {
            ++dropped["road_not_at_surface"];
            continue;
        }
        if (r.area) {
            ++dropped["road_area_not_a_line"];
            continue;
        }
        const std::vector<Vec2d> line = cleanLine(r.centerline);
        if (line.size() < 2) {
            ++dropped["road_degenerate"];
            continue;
        }
        cutAtBuildings(footprints, line, i, r, runs, cut);
    }
    if (cut > 0) dropped["road_piece_in_building"] += cut;

    // Nodes of the two graphs: a vertex used twice among carriageways (or among paths) splits there;
    // a path is split where it touches a carriageway too (the street network trims it at the curb).
    std::unordered_map<PointKey, uint32_t, PointKeyHash> uses[2];
    for (const Run& run : runs)
        for (const Vec2d& p : run.points) ++uses[isPath(city.roads[run.road].highway)][PointKey(p)];
    const auto isNode = [&](const Run& run, Vec2d p) {
        const bool path = isPath(city.roads[run.road].highway);
        const auto it = uses[path].find(PointKey(p));
        return (it != uses[path].end() && it->second >= 2) || (path && uses[0].count(PointKey(p)) > 0);
    };

    const MappedSidewalks mapped(city.roads);
    std::vector<Road> fitted;
    for (const Run& run : runs) {
        size_t from = 0;
        for (size_t i = 1; i < run.points.size(); ++i) {
            if (i + 1 < run.points.size() && !isNode(run, run.points[i])) continue;
            const Road& way = city.roads[run.road];
            Road edge = way;
            edge.centerline.assign(run.points.begin() + long(from), run.points.begin() + long(i) + 1);
            double left = kInfinity, right = kInfinity;
            for (size_t k = from; k < i; ++k) {
                left = std::min(left, run.left[k]);
                right = std::min(right, run.right[k]);
            }
            fitWidths(edge, footprints, mapped, left, right);
            fitted.push_back(std::move(edge));
            from = i;
        }
    }
    return fitted;
}

} // namespace urbis
