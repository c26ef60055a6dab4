#include "citygen/roof_shapes.h"

#include "citygen/ear_clipping.h"

#include <cmath>

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

/// Calls `triangle` for each triangle of each skeleton face, with s the skeleton time; false if a face fails.
template <typename F>
bool forEachSkeletonTriangle(const StraightSkeleton& skeleton, F&& triangle) {
    std::vector<std::vector<std::array<uint32_t, 3>>> faces;
    for (const std::vector<uint32_t>& face : skeleton.faces) {
        std::vector<Vec2d> ring;
        for (uint32_t i : face) ring.push_back(skeleton.points[i]);
        faces.push_back(earClip(ring));
        if (faces.back().empty()) return false;
    }
    for (size_t f = 0; f < faces.size(); ++f)
        for (const auto& t : faces[f]) {
            std::array<LevelPoint, 3> tri;
            for (size_t k = 0; k < 3; ++k) {
                const uint32_t i = skeleton.faces[f][t[k]];
                tri[k] = {skeleton.points[i], skeleton.times[i]};
            }
            triangle(tri);
        }
    return true;
}

} // namespace

void meshFlatRoof(const FootprintTriangles& footprint, RoofSink& sink) {
    // Triangles are two-sided for both backends, so GEOS's winding needs no fixing.
    for (const auto& t : footprint) sink.roof(sink.at(t[0], 0), sink.at(t[1], 0), sink.at(t[2], 0));
}

bool meshParapetRoof(const StraightSkeleton& skeleton, double parapetHeight, double thickness, RoofSink& sink) {
    const std::vector<double> cuts{thickness};
    return forEachSkeletonTriangle(skeleton, [&](const std::array<LevelPoint, 3>& tri) {
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
    return forEachSkeletonTriangle(skeleton, [&](const std::array<LevelPoint, 3>& tri) {
        emitProfiledTriangle(tri, profile, sink);
    });
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
