#include "citygen/roof_shapes.h"

#include "citygen/ear_clipping.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace urbis {

namespace {

/// The area centroid of a simple ring.
Vec2d areaCentroid(const Ring& ring) {
    double area = 0, cx = 0, cy = 0;
    for (size_t i = 0; i < ring.size(); ++i) {
        const Vec2d a = ring[i], b = ring[(i + 1) % ring.size()];
        const double w = a.x * b.y - b.x * a.y;
        area += w;
        cx += (a.x + b.x) * w;
        cy += (a.y + b.y) * w;
    }
    return {cx / (3 * area), cy / (3 * area)};
}

/// The skeleton's faces as rings of level points, s the skeleton time.
std::vector<std::vector<LevelPoint>> skeletonRings(const StraightSkeleton& skeleton) {
    std::vector<std::vector<LevelPoint>> rings;
    for (const std::vector<uint32_t>& face : skeleton.faces) {
        rings.emplace_back();
        for (uint32_t i : face) rings.back().push_back({skeleton.points[i], skeleton.times[i]});
    }
    return rings;
}

/// Calls `triangle(points, ring)` for each triangle of each ring; false (calling nothing) if a ring
/// cannot be triangulated.
template <typename F>
bool forEachRingTriangle(const std::vector<std::vector<LevelPoint>>& rings, F&& triangle) {
    std::vector<std::vector<std::array<uint32_t, 3>>> triangles;
    for (const std::vector<LevelPoint>& ring : rings) {
        std::vector<Vec2d> points;
        for (const LevelPoint& p : ring) points.push_back(p.p);
        triangles.push_back(earClip(points));
        if (triangles.back().empty()) return false;
    }
    for (size_t f = 0; f < rings.size(); ++f)
        for (const auto& t : triangles[f]) triangle(std::array<LevelPoint, 3>{rings[f][t[0]], rings[f][t[1]], rings[f][t[2]]}, f);
    return true;
}

/// The band of a skeleton face (`ring`) when it is the quad p0 p1 q1 q0: the face's contour edge
/// and the crossings of its arcs from the edge's ends with s = thickness, computed as forEachSlab
/// cuts a triangle's edge (so bit-identical to where a neighbouring face's pieces cut the arc);
/// `deck` is then the rest of the face: q1, the face's other vertices, q0.
std::optional<ParapetBand> quadBand(const std::vector<LevelPoint>& ring, double thickness, std::vector<LevelPoint>& deck) {
    const size_t n = ring.size();
    size_t k = n;
    for (size_t i = 0; i < n; ++i)
        if (ring[i].s == 0.0 && ring[(i + 1) % n].s == 0.0) k = i;
    if (k == n || n < 3) return std::nullopt;
    for (size_t i = 2; i < n; ++i)
        if (ring[(k + i) % n].s < thickness) return std::nullopt;
    auto crossing = [&](LevelPoint end, LevelPoint arc) {
        std::vector<LevelPoint> cut;
        appendCutEdge(end, arc, {thickness}, cut);
        return cut.size() == 2 ? cut[1] : arc;
    };
    const LevelPoint p0 = ring[k], p1 = ring[(k + 1) % n];
    const LevelPoint q0 = crossing(p0, ring[(k + n - 1) % n]), q1 = crossing(p1, ring[(k + 2) % n]);
    deck = {q1};
    for (size_t i = 2; i < n; ++i) {
        const LevelPoint& v = ring[(k + i) % n];
        if ((i == 2 || i + 1 == n) && v.s == thickness) continue;  // q1 or q0 itself
        deck.push_back(v);
    }
    deck.push_back(q0);
    if (deck.size() < 3) return std::nullopt;  // the band is a triangle
    return ParapetBand{p0.p, p1.p, q0.p, q1.p};
}

/// Rings of up to this many vertices get their deck as one inset ring (ear clipping is quadratic).
constexpr size_t kMaxInsetDeckVertices = 64;

/// The deck as one ring when every face's band is a quad and the footprint has no holes: the bands'
/// inner corners in ring order (q1 of one band is q0 of the next, bit for bit), ear-clipped: n - 2
/// triangles instead of one polygon per skeleton face. Empty when that does not apply.
std::vector<std::array<Vec2d, 3>> insetDeck(const std::vector<ParapetBand>& bands) {
    if (bands.size() < 3 || bands.size() > kMaxInsetDeckVertices) return {};
    std::vector<Vec2d> ring{bands[0].q0};
    Vec2d at = bands[0].p1;
    for (size_t step = 1; step < bands.size(); ++step) {
        auto next = std::find_if(bands.begin(), bands.end(), [&](const ParapetBand& b) { return b.p0.x == at.x && b.p0.y == at.y; });
        if (next == bands.end() || next == bands.begin()) return {};  // more than one ring: holes
        ring.push_back(next->q0);
        at = next->p1;
    }
    if (at.x != bands[0].p0.x || at.y != bands[0].p0.y) return {};
    std::vector<std::array<Vec2d, 3>> triangles;
    for (const auto& t : earClip(ring)) triangles.push_back({ring[t[0]], ring[t[1]], ring[t[2]]});
    return triangles;
}

} // namespace

void meshFlatRoof(const FootprintTriangles& footprint, RoofSink& sink) {
    // Triangles are two-sided for both backends, so GEOS's winding needs no fixing.
    for (const auto& t : footprint) sink.roof(sink.at(t[0], 0), sink.at(t[1], 0), sink.at(t[2], 0));
}

bool meshParapetRoof(const StraightSkeleton& skeleton, double parapetHeight, double thickness, RoofSink& sink,
                     std::vector<ParapetBand>& bands) {
    // A face whose band is a quad keeps only its deck (the face beyond the band); the others are
    // cut at the thickness into band and deck, with the inner face along each cut.
    std::vector<std::vector<LevelPoint>> rings = skeletonRings(skeleton);
    std::vector<bool> quad(rings.size());
    std::vector<ParapetBand> found;
    for (size_t f = 0; f < rings.size(); ++f) {
        std::vector<LevelPoint> deck;
        if (std::optional<ParapetBand> band = quadBand(rings[f], thickness, deck)) {
            quad[f] = true;
            found.push_back(*band);
            rings[f] = std::move(deck);
        }
    }
    if (found.size() == rings.size()) {
        const std::vector<std::array<Vec2d, 3>> deck = insetDeck(found);
        if (!deck.empty()) {
            for (const auto& t : deck)
                sink.roof(sink.at(t[0], -parapetHeight), sink.at(t[1], -parapetHeight), sink.at(t[2], -parapetHeight));
            bands.insert(bands.end(), found.begin(), found.end());
            return true;
        }
    }
    const std::vector<double> cuts{thickness};
    const bool done = forEachRingTriangle(rings, [&](const std::array<LevelPoint, 3>& tri, size_t face) {
        if (quad[face]) {
            sink.roof(sink.at(tri[0].p, -parapetHeight), sink.at(tri[1].p, -parapetHeight), sink.at(tri[2].p, -parapetHeight));
            return;
        }
        forEachSlab(tri, cuts, [&](const std::vector<LevelPoint>& part, size_t slab) {
            const double h = slab == 0 ? 0.0 : -parapetHeight;
            for (size_t i = 1; i + 1 < part.size(); ++i) {
                const Vec3f a = sink.at(part[0].p, h), b = sink.at(part[i].p, h), c = sink.at(part[i + 1].p, h);
                slab == 0 ? sink.wall(a, b, c) : sink.roof(a, b, c);
            }
            if (slab == 0) return;
            // The parapet's inner face stands on the deck piece's edges along the offset line.
            for (size_t i = 0; i < part.size(); ++i) {
                const LevelPoint& p = part[i];
                const LevelPoint& q = part[(i + 1) % part.size()];
                if (p.s != thickness || q.s != thickness) continue;
                sink.wall(sink.at(p.p, 0), sink.at(q.p, 0), sink.at(q.p, -parapetHeight));
                sink.wall(sink.at(p.p, 0), sink.at(q.p, -parapetHeight), sink.at(p.p, -parapetHeight));
            }
        });
    });
    if (done) bands.insert(bands.end(), found.begin(), found.end());
    return done;
}

void meshParapetBand(const ParapetBand& band, double parapetHeight, RoofSink& sink) {
    const Vec3f p0 = sink.at(band.p0, 0), p1 = sink.at(band.p1, 0), q0 = sink.at(band.q0, 0), q1 = sink.at(band.q1, 0);
    sink.wall(p0, p1, q1);
    sink.wall(p0, q1, q0);
    const Vec3f d0 = sink.at(band.q0, -parapetHeight), d1 = sink.at(band.q1, -parapetHeight);
    sink.wall(d0, d1, q1);
    sink.wall(d0, q1, q0);
}

void meshRidgeRoof(const Polygon& polygon, const FootprintTriangles& footprint, Vec2d across,
                   const RoofProfile& profile, RoofSink& sink) {
    auto level = [&](Vec2d p) {
        double s = p.x * across.x + p.y * across.y;
        for (double b : profile.s)
            if (std::abs(s - b) < 1e-7) s = b;
        return LevelPoint{p, s};
    };
    for (const auto& t : footprint) emitProfiledTriangle({level(t[0]), level(t[1]), level(t[2])}, profile, sink);
    auto gables = [&](const Ring& ring) {
        for (size_t i = 0; i < ring.size(); ++i)
            emitWallUnderRoof(level(ring[i]), level(ring[(i + 1) % ring.size()]), profile, sink);
    };
    gables(polygon.outer);
    for (const Ring& hole : polygon.holes) gables(hole);
}

bool meshSkeletonRoof(const StraightSkeleton& skeleton, const RoofProfile& profile, RoofSink& sink) {
    return forEachRingTriangle(skeletonRings(skeleton), [&](const std::array<LevelPoint, 3>& tri, size_t) {
        emitProfiledTriangle(tri, profile, sink);
    });
}

bool meshGabledSkeletonRoof(const StraightSkeleton& skeleton, const RoofProfile& profile, RoofSink& sink) {
    // A wing's end is a face that is a triangle over its edge, whose apex only the two faces beside
    // it share and lies over the edge itself (well inside it).
    std::vector<int> facesAt(skeleton.points.size(), 0);
    for (const std::vector<uint32_t>& face : skeleton.faces)
        for (uint32_t i : face) ++facesAt[i];
    auto endApex = [&](const std::vector<uint32_t>& face) {
        int apex = -1, corners = 0;
        for (uint32_t i : face) {
            if (skeleton.times[i] > 0.0) apex = int(i);
            else ++corners;
        }
        return face.size() == 3 && corners == 2 && apex >= 0 && facesAt[size_t(apex)] == 3 ? apex : -1;
    };
    struct Gable {
        Vec2d a, b;
        uint32_t top;
    };
    std::vector<Gable> gables;
    std::vector<bool> isGable(skeleton.faces.size(), false);
    StraightSkeleton moved = skeleton;
    for (size_t f = 0; f < skeleton.faces.size(); ++f) {
        const std::vector<uint32_t>& face = skeleton.faces[f];
        const int apex = endApex(face);
        if (apex < 0) continue;
        size_t k = 0;
        while (face[k] != uint32_t(apex)) ++k;
        const Vec2d a = skeleton.points[face[(k + 1) % 3]], b = skeleton.points[face[(k + 2) % 3]];
        const Vec2d n = skeleton.points[size_t(apex)];
        const double along = ((n.x - a.x) * (b.x - a.x) + (n.y - a.y) * (b.y - a.y)) /
                             ((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y));
        if (!(along > 0.05 && along < 0.95)) continue;
        moved.points[size_t(apex)] = {a.x + along * (b.x - a.x), a.y + along * (b.y - a.y)};
        gables.push_back({a, b, uint32_t(apex)});
        isGable[f] = true;
    }
    const std::vector<std::vector<LevelPoint>> faces = skeletonRings(moved);
    std::vector<std::vector<LevelPoint>> rings;   // the roof's faces: all but the gables
    for (size_t f = 0; f < faces.size(); ++f)
        if (!isGable[f]) rings.push_back(faces[f]);
    if (!forEachRingTriangle(rings, [&](const std::array<LevelPoint, 3>& tri, size_t) { emitProfiledTriangle(tri, profile, sink); }))
        return false;
    for (const Gable& g : gables) {
        const Vec2d top = moved.points[g.top];
        sink.wall(sink.at(g.a, 0.0), sink.at(g.b, 0.0), sink.at(top, profile.at(moved.times[g.top])));
    }
    return true;
}

void meshPyramidRoof(const Ring& outer, double height, RoofSink& sink) {
    const Vec3f apex = sink.at(areaCentroid(outer), height);
    for (size_t i = 0; i < outer.size(); ++i)
        sink.roof(sink.at(outer[i], 0), sink.at(outer[(i + 1) % outer.size()], 0), apex);
}

void meshRevolvedRoof(const Ring& outer, const std::vector<RevolutionStep>& steps, RoofSink& sink) {
    const Vec2d c = areaCentroid(outer);
    auto ringPoint = [&](size_t i, const RevolutionStep& step) {
        if (step.scale == 1.0) return sink.at(outer[i], step.height);  // bit-identical to the wall top
        const Vec2d p = outer[i];
        return sink.at({c.x + step.scale * (p.x - c.x), c.y + step.scale * (p.y - c.y)}, step.height);
    };
    const Vec3f apex = sink.at(c, steps.back().height);
    for (size_t k = 0; k + 1 < steps.size(); ++k)
        for (size_t i = 0; i < outer.size(); ++i) {
            const size_t j = (i + 1) % outer.size();
            const Vec3f a0 = ringPoint(i, steps[k]), b0 = ringPoint(j, steps[k]);
            if (k + 2 == steps.size()) {
                sink.roof(a0, b0, apex);
                continue;
            }
            const Vec3f a1 = ringPoint(i, steps[k + 1]), b1 = ringPoint(j, steps[k + 1]);
            sink.roof(a0, b0, b1);
            sink.roof(a0, b1, a1);
        }
}

} // namespace urbis
