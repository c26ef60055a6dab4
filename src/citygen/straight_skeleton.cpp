// The only file that includes CGAL: it compiles slowly and needs -frounding-math (CMakeLists.txt).
#include "citygen/straight_skeleton.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/create_straight_skeleton_2.h>

#include <cmath>
#include <map>

namespace urbis {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalPolygon = CGAL::Polygon_2<Kernel>;

CgalPolygon cgalPolygon(const Ring& ring) {
    CgalPolygon polygon;
    for (const Vec2d& p : ring) polygon.push_back(Kernel::Point_2(p.x, p.y));
    return polygon;
}

/// Merges points closer than `tolerance` (the skeleton of symmetric footprints has several nodes at one place).
class PointMerger {
public:
    explicit PointMerger(StraightSkeleton& out) : out_(out) {}
    uint32_t indexOf(Vec2d p, double time) {
        const double cell = 1e-6;
        const auto key = std::make_pair(std::llround(p.x / cell), std::llround(p.y / cell));
        for (long dx = -1; dx <= 1; ++dx)
            for (long dy = -1; dy <= 1; ++dy) {
                auto it = cells_.find({key.first + dx, key.second + dy});
                if (it == cells_.end()) continue;
                const Vec2d q = out_.points[it->second];
                if (std::abs(q.x - p.x) <= cell && std::abs(q.y - p.y) <= cell) return it->second;
            }
        const uint32_t index = uint32_t(out_.points.size());
        out_.points.push_back(p);
        out_.times.push_back(time);
        cells_.emplace(key, index);
        return index;
    }

private:
    StraightSkeleton& out_;
    std::map<std::pair<long long, long long>, uint32_t> cells_;
};

} // namespace

std::optional<StraightSkeleton> interiorStraightSkeleton(const Polygon& footprint) {
    if (footprint.outer.size() < 3) return std::nullopt;
    const CgalPolygon outer = cgalPolygon(footprint.outer);
    std::vector<CgalPolygon> holes;
    for (const Ring& hole : footprint.holes) holes.push_back(cgalPolygon(hole));
    const auto skeleton = CGAL::create_interior_straight_skeleton_2(outer.vertices_begin(), outer.vertices_end(),
                                                                    holes.begin(), holes.end(), Kernel());
    if (!skeleton) return std::nullopt;

    StraightSkeleton out;
    PointMerger merger(out);
    // Contour points first, so that they keep their exact input coordinates.
    std::map<int, uint32_t> indexOfVertex;
    for (auto v = skeleton->vertices_begin(); v != skeleton->vertices_end(); ++v)
        if (v->is_contour()) indexOfVertex[v->id()] = merger.indexOf({v->point().x(), v->point().y()}, 0.0);
    for (auto v = skeleton->vertices_begin(); v != skeleton->vertices_end(); ++v)
        if (v->is_skeleton()) {
            const double time = v->time();
            if (!std::isfinite(time) || !std::isfinite(v->point().x()) || !std::isfinite(v->point().y())) return std::nullopt;
            indexOfVertex[v->id()] = merger.indexOf({v->point().x(), v->point().y()}, time);
            out.maxTime = std::max(out.maxTime, time);
        }
    for (auto f = skeleton->faces_begin(); f != skeleton->faces_end(); ++f) {
        std::vector<uint32_t> face;
        auto h = f->halfedge();
        const auto start = h;
        do {
            const uint32_t index = indexOfVertex.at(h->vertex()->id());
            if (face.empty() || face.back() != index) face.push_back(index);
            h = h->next();
        } while (h != start);
        while (face.size() > 1 && face.front() == face.back()) face.pop_back();
        if (face.size() >= 3) out.faces.push_back(std::move(face));
    }
    if (out.faces.empty() || out.maxTime <= 0) return std::nullopt;
    return out;
}

} // namespace urbis
