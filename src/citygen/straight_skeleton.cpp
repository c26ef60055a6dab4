// The only file that includes CGAL: it compiles slowly and needs -frounding-math (CMakeLists.txt).
#include "citygen/straight_skeleton.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Straight_skeleton_builder_2.h>

#include <cmath>
#include <map>
#include <stdexcept>

namespace urbis {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Skeleton = CGAL::Straight_skeleton_2<Kernel>;

/// Stops a skeleton whose construction does not end: the builder catches what its visitor throws
/// and returns no skeleton. A skeleton has fewer nodes than twice its contour's vertices, each made
/// by one event; a builder that loops processes events without end.
class EventBudget : public CGAL::Dummy_straight_skeleton_builder_2_visitor<Skeleton> {
public:
    explicit EventBudget(size_t contourVertices) : left_(kEventsPerVertex * contourVertices + 64) {}
    void on_edge_event_processed(const Vertex_const_handle&, const Vertex_const_handle&, const Vertex_const_handle&) const { spend(); }
    void on_split_event_processed(const Vertex_const_handle&, const Vertex_const_handle&, const Vertex_const_handle&) const { spend(); }
    void on_pseudo_split_event_processed(const Vertex_const_handle&, const Vertex_const_handle&, const Vertex_const_handle&,
                                         const Vertex_const_handle&) const { spend(); }

private:
    static constexpr size_t kEventsPerVertex = 16;
    void spend() const {
        if (left_-- == 0) throw std::runtime_error("straight skeleton: event budget spent");
    }
    mutable size_t left_;  // the builder calls its visitor through a const reference
};

using Builder = CGAL::Straight_skeleton_builder_2<CGAL::Straight_skeleton_builder_traits_2<Kernel>, Skeleton, EventBudget>;

/// CGAL's skeleton of the footprint, or null where CGAL gives none, throws or would take too long.
boost::shared_ptr<Skeleton> cgalSkeleton(const Polygon& footprint) {
    size_t vertices = footprint.outer.size();
    for (const Ring& hole : footprint.holes) vertices += hole.size();
    if (vertices > kMaxSkeletonVertices) return nullptr;
    auto points = [](const Ring& ring) {
        std::vector<Kernel::Point_2> out;
        for (const Vec2d& p : ring) out.emplace_back(p.x, p.y);
        return out;
    };
    try {
        const EventBudget budget(vertices);
        Builder builder(boost::none, Builder::Traits(), budget);
        const std::vector<Kernel::Point_2> outer = points(footprint.outer);
        builder.enter_contour(outer.begin(), outer.end());
        for (const Ring& hole : footprint.holes) {
            const std::vector<Kernel::Point_2> ring = points(hole);
            builder.enter_contour(ring.begin(), ring.end());
        }
        return builder.construct_skeleton();
    } catch (const std::exception&) {  // CGAL::Failure_exception: CGAL_error(), and in Debug builds every assertion
        return nullptr;
    }
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
    const boost::shared_ptr<Skeleton> skeleton = cgalSkeleton(footprint);
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
