#include "streets/bridge_deck.h"

#include "streets/polyline.h"
#include "streets/street_levels.h"

#include <algorithm>
#include <cmath>

namespace urbis {

namespace {

/// One edge's parapet: outer face over the deck's side, top, inner face; closed at the ends asked for.
size_t addParapet(TriangleMesh& mesh, const std::vector<Vec2d>& line, double edgeOffset, double inward,
                  const std::vector<float>& base, const DeckShape& shape, TriangleInfo info) {
    const std::vector<Vec2d> outer = offsetPolyline(line, edgeOffset);
    const std::vector<Vec2d> inner = offsetPolyline(line, edgeOffset + inward);
    const std::vector<float> top = raised(base, kParapetHeight);
    size_t n = addRibbon(mesh, outer, base, outer, top, info) + addRibbon(mesh, inner, base, inner, top, info) +
               addRibbon(mesh, outer, top, inner, top, info);
    const size_t last = line.size() - 1;
    for (size_t end : {size_t(0), last}) {
        if (!(end == 0 ? shape.closeStart : shape.closeEnd)) continue;
        n += addQuad(mesh, worldFromStreet(outer[end], base[end]), worldFromStreet(inner[end], base[end]),
                     worldFromStreet(inner[end], top[end]), worldFromStreet(outer[end], top[end]), info);
    }
    return n;
}

} // namespace

size_t addQuad(TriangleMesh& mesh, Vec3f a, Vec3f b, Vec3f c, Vec3f d, TriangleInfo info) {
    mesh.add({a, b, c}, info);
    mesh.add({a, c, d}, info);
    return 2;
}

size_t addRibbon(TriangleMesh& mesh, const std::vector<Vec2d>& a, const std::vector<float>& hA,
                 const std::vector<Vec2d>& b, const std::vector<float>& hB, TriangleInfo info) {
    size_t n = 0;
    for (size_t i = 1; i < a.size(); ++i) {
        const bool repeated = a[i].x == a[i - 1].x && a[i].y == a[i - 1].y && b[i].x == b[i - 1].x && b[i].y == b[i - 1].y;
        if (repeated) continue;
        n += addQuad(mesh, worldFromStreet(a[i - 1], hA[i - 1]), worldFromStreet(a[i], hA[i]),
                     worldFromStreet(b[i], hB[i]), worldFromStreet(b[i - 1], hB[i - 1]), info);
    }
    return n;
}

std::vector<float> raised(const std::vector<float>& base, float offset) {
    std::vector<float> out(base.size());
    for (size_t i = 0; i < base.size(); ++i) out[i] = base[i] + offset;
    return out;
}

bool meshableLine(const std::vector<Vec2d>& line) {
    if (line.size() < 2) return false;
    for (const Vec2d& p : line)
        if (!(std::fabs(p.x) < 1e7 && std::fabs(p.y) < 1e7)) return false;
    return polylineLength(line) > 0.01;
}

size_t meshDeck(const std::vector<Vec2d>& line, const std::vector<float>& elevation, const DeckShape& shape,
                TriangleInfo deck, TriangleInfo parapet, TriangleMesh& mesh) {
    if (line.size() < 2 || elevation.size() != line.size()) return 0;
    const std::vector<Vec2d> left = offsetPolyline(line, shape.leftWidth);
    const std::vector<Vec2d> right = offsetPolyline(line, -shape.rightWidth);
    const std::vector<float> leftTop = raised(elevation, shape.leftLevel);
    const std::vector<float> rightTop = raised(elevation, shape.rightLevel);
    const std::vector<float> ground(line.size(), 0.0f);
    const std::vector<float> underside = raised(elevation, kRoadLevel - kDeckThickness);
    const std::vector<float>& bottom = shape.embankment ? ground : underside;

    size_t n = addRibbon(mesh, left, bottom, left, leftTop, deck) + addRibbon(mesh, right, bottom, right, rightTop, deck);
    if (!shape.embankment) n += addRibbon(mesh, left, underside, right, underside, deck);
    if (shape.top) n += addRibbon(mesh, left, leftTop, right, rightTop, deck);
    const size_t last = line.size() - 1;
    for (size_t end : {size_t(0), last}) {
        if (!(end == 0 ? shape.closeStart : shape.closeEnd)) continue;
        n += addQuad(mesh, worldFromStreet(left[end], 0.0), worldFromStreet(right[end], 0.0),
                     worldFromStreet(right[end], rightTop[end]), worldFromStreet(left[end], leftTop[end]), deck);
    }
    n += addParapet(mesh, line, shape.leftWidth, -kParapetThickness, leftTop, shape, parapet);
    n += addParapet(mesh, line, -shape.rightWidth, kParapetThickness, rightTop, shape, parapet);
    return n;
}

size_t meshEmbankments(const std::vector<Vec2d>& line, const std::vector<float>& elevation, DeckShape shape,
                       TriangleInfo deck, TriangleInfo parapet, TriangleMesh& mesh) {
    if (elevation.size() != line.size()) return 0;
    shape.embankment = true;
    size_t n = 0;
    for (size_t begin = 0; begin + 1 < line.size();) {
        if (std::max(elevation[begin], elevation[begin + 1]) <= 0.0f) {
            ++begin;
            continue;
        }
        size_t end = begin + 1;
        while (end + 1 < line.size() && std::max(elevation[end], elevation[end + 1]) > 0.0f) ++end;
        const std::vector<Vec2d> run(line.begin() + long(begin), line.begin() + long(end) + 1);
        const std::vector<float> lift(elevation.begin() + long(begin), elevation.begin() + long(end) + 1);
        n += meshDeck(run, lift, shape, deck, parapet, mesh);
        begin = end;
    }
    return n;
}

} // namespace urbis
