#include "accel/split_references.h"

#include <algorithm>
#include <cmath>

namespace urbis {
namespace {

/// A convex piece of a triangle: each cut adds at most one corner, so a piece cut `depth` times has at
/// most 3 + depth (split() stops before kMaxCorners).
struct Piece {
    static constexpr int kMaxCorners = 16;
    Vec3f corner[kMaxCorners];
    int count = 0;

    Bounds3f bounds() const {
        Bounds3f b;
        for (int i = 0; i < count; ++i) b.extend(corner[i]);
        return b;
    }
    /// Area of the (planar, convex) piece: half the length of the sum of its fan's cross products.
    float area() const {
        Vec3f sum{0, 0, 0};
        for (int i = 1; i + 1 < count; ++i) sum = sum + cross(corner[i] - corner[0], corner[i + 1] - corner[0]);
        return 0.5f * length(sum);
    }
};

/// The parts of `p` below and above the plane x[axis] = at (Sutherland-Hodgman against each side).
void cut(const Piece& p, int axis, float at, Piece& below, Piece& above) {
    below.count = above.count = 0;
    for (int i = 0; i < p.count; ++i) {
        const Vec3f u = p.corner[i], v = p.corner[(i + 1) % p.count];
        if (u[axis] <= at) below.corner[below.count++] = u;
        if (u[axis] >= at) above.corner[above.count++] = u;
        if ((u[axis] < at && v[axis] > at) || (u[axis] > at && v[axis] < at)) {
            const float s = (at - u[axis]) / (v[axis] - u[axis]);
            Vec3f x = u + (v - u) * s;
            x[axis] = at;
            below.corner[below.count++] = x;
            above.corner[above.count++] = x;
        }
    }
}

void split(const Piece& p, const Bounds3f& whole, const SplitOptions& options, int depth, std::vector<Bounds3f>& out) {
    const Bounds3f box = p.bounds();
    const Vec3f e = box.extent();
    const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
    const float halfArea = e.x * e.y + e.y * e.z + e.z * e.x;
    if (depth < std::min(options.maxDepth, Piece::kMaxCorners - 3) && e[axis] > options.minExtent && halfArea > options.maxAreaRatio * p.area()) {
        Piece below, above;
        cut(p, axis, box.lo[axis] + 0.5f * e[axis], below, above);
        if (below.count >= 3 && above.count >= 3) {
            split(below, whole, options, depth + 1, out);
            split(above, whole, options, depth + 1, out);
            return;
        }
    }
    // Widened against the rounding of the clipped corners (a millimetre and some 8 ulps), never
    // beyond the triangle's own box.
    Bounds3f widened;
    for (int k = 0; k < 3; ++k) {
        const float margin = 1e-3f + 1e-6f * std::max(std::abs(box.lo[k]), std::abs(box.hi[k]));
        widened.lo[k] = std::max(box.lo[k] - margin, whole.lo[k]);
        widened.hi[k] = std::min(box.hi[k] + margin, whole.hi[k]);
    }
    out.push_back(widened);
}

} // namespace

void splitTriangleBounds(Vec3f a, Vec3f b, Vec3f c, const SplitOptions& options, std::vector<Bounds3f>& out) {
    Piece p;
    p.corner[0] = a;
    p.corner[1] = b;
    p.corner[2] = c;
    p.count = 3;
    split(p, p.bounds(), options, 0, out);
}

} // namespace urbis
