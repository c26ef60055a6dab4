#include "citygen/city_on_terrain.h"

#include "scene/surface_part.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace urbis {
namespace {

/// Whether a triangle of this part belongs to the streets (roads to lamps) rather than a building.
bool isStreetPart(uint32_t part) { return part >= uint32_t(SurfacePart::Road); }

/// Vertices this close (metres) to a building's base are its base, and follow the lowest ground.
constexpr float kBaseTolerance = 0.01f;

/// Splits `t` in four at its edges' midpoints until no edge is longer than `edge`, into `out`.
void subdivide(const Triangle& t, float edge, std::vector<Triangle>& out) {
    auto len2 = [](Vec3f a, Vec3f b) { return dot(a - b, a - b); };
    const float longest = std::max({len2(t.p0, t.p1), len2(t.p1, t.p2), len2(t.p2, t.p0)});
    if (longest <= edge * edge) {
        out.push_back(t);
        return;
    }
    const Vec3f a = (t.p0 + t.p1) * 0.5f, b = (t.p1 + t.p2) * 0.5f, c = (t.p2 + t.p0) * 0.5f;
    subdivide({t.p0, a, c}, edge, out);
    subdivide({a, t.p1, b}, edge, out);
    subdivide({c, b, t.p2}, edge, out);
    subdivide({a, b, c}, edge, out);
}

} // namespace

float streetEdgeOnTerrain(const TerrainField& terrain) { return 2.0f * terrain.record.cell; }

void placeCityOnTerrain(CityMesh& mesh, const TerrainField& terrain) {
    // Each building's box, from its triangles and its walls' bottom edges.
    std::unordered_map<uint32_t, Bounds3f> buildings;   // each building's box
    TriangleMesh& tris = mesh.mesh;
    for (size_t i = 0; i < tris.size(); ++i) {
        if (isStreetPart(tris.info[i].part)) continue;
        Bounds3f& box = buildings[tris.info[i].object];
        for (const Vec3f p : {tris.triangles[i].p0, tris.triangles[i].p1, tris.triangles[i].p2}) box.extend(p);
    }
    for (const WallRecord& w : mesh.walls) {
        Bounds3f& box = buildings[w.object];
        box.extend(w.origin);
        box.extend(w.origin + w.axisU * w.width);
    }
    // Entrance (the highest ground under the box) and base (the lowest) of each building.
    struct Levels {
        float bottom, entrance, base;
    };
    std::unordered_map<uint32_t, Levels> levels;
    for (const auto& [object, box] : buildings) {
        float lo, hi;
        terrain.rangeIn(box.lo.x, box.lo.z, box.hi.x, box.hi.z, lo, hi);
        levels[object] = {box.lo.y, hi, lo};
    }
    // A building's vertex rises by its entrance level; one at its base goes down to the lowest ground.
    auto lift = [&](Vec3f& p, const Levels& l) {
        p.y = p.y <= l.bottom + kBaseTolerance ? l.base + (p.y - l.bottom) : p.y + l.entrance;
    };
    TriangleMesh lifted;
    lifted.triangles.reserve(tris.size());
    lifted.info.reserve(tris.size());
    std::vector<Triangle> pieces;
    const float edge = streetEdgeOnTerrain(terrain);
    for (size_t i = 0; i < tris.size(); ++i) {
        const TriangleInfo info = tris.info[i];
        if (!isStreetPart(info.part)) {
            Triangle t = tris.triangles[i];
            const Levels& l = levels.at(info.object);
            lift(t.p0, l), lift(t.p1, l), lift(t.p2, l);
            lifted.add(t, info);
            continue;
        }
        // Street surfaces follow the ground vertex by vertex, in pieces short enough to stay on it.
        pieces.clear();
        subdivide(tris.triangles[i], edge, pieces);
        for (Triangle& t : pieces) {
            for (Vec3f* p : {&t.p0, &t.p1, &t.p2}) p->y += terrain.heightAt(p->x, p->z);
            lifted.add(t, info);
        }
    }
    tris = std::move(lifted);
    for (WallRecord& w : mesh.walls) {
        const Levels& l = levels.at(w.object);
        if (w.origin.y <= l.bottom + kBaseTolerance) {
            // Down to the lowest ground, the cell grid kept where it was: floors count from the entrance.
            const float drop = l.entrance - l.base;
            w.origin.y += l.base - l.bottom;
            w.height += drop;
            w.gridV += drop;
        } else {
            w.origin.y += l.entrance;
        }
    }
    for (LampRecord& lamp : mesh.lamps) lamp.base.y += terrain.heightAt(lamp.base.x, lamp.base.z);
    // The framing follows the ground under each piece; the city's bounds take every building's lift.
    for (Bounds3f& piece : mesh.framingPieces) {
        if (piece.empty()) continue;
        float lo, hi;
        terrain.rangeIn(piece.lo.x, piece.lo.z, piece.hi.x, piece.hi.z, lo, hi);
        piece.lo.y += lo;
        piece.hi.y += hi;
    }
    if (!mesh.cityBounds.empty()) {
        float lo, hi;
        terrain.rangeIn(mesh.cityBounds.lo.x, mesh.cityBounds.lo.z, mesh.cityBounds.hi.x, mesh.cityBounds.hi.z, lo, hi);
        mesh.cityBounds.lo.y += lo;
        mesh.cityBounds.hi.y += hi;
    }
}

} // namespace urbis
