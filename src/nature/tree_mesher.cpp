#include "nature/tree_mesher.h"

#include "math/constants.h"
#include "scene/surface_part.h"
#include "scene/tree_shape.h"

#include <cmath>

namespace urbis {

namespace {

/// Radius of a regular n-gon with the area of a circle of radius 1.
float ringScale(int sides) { return float(std::sqrt(2.0 * kPi / (sides * std::sin(2.0 * kPi / sides)))); }

struct TreeMesher {
    const TreeRecord& tree;
    TriangleMesh& mesh;
    size_t added = 0;

    void triangle(Vec3f a, Vec3f b, Vec3f c, TreeMaterial material, SurfacePart part) {
        const TriangleInfo info{tree.material + uint32_t(material), tree.object, uint32_t(part)};
        mesh.add({tree.base + a, tree.base + b, tree.base + c}, info);
        ++added;
    }
    void quad(Vec3f a, Vec3f b, Vec3f c, Vec3f d, TreeMaterial material, SurfacePart part) {
        triangle(a, b, c, material, part);
        triangle(a, c, d, material, part);
    }

    /// A prism (a frustum of `sides` faces, no caps) from `a` (radius ra) to `b` (radius rb).
    void prism(Vec3f a, Vec3f b, float ra, float rb, int sides) {
        const Vec3f axis = normalize(b - a);
        const Vec3f helper = std::fabs(axis.y) < 0.9f ? Vec3f{0, 1, 0} : Vec3f{1, 0, 0};
        const Vec3f u = normalize(cross(axis, helper)), v = cross(axis, u);
        const float scale = ringScale(sides);
        const auto ring = [&](Vec3f c, float r, int k) {
            const float angle = 2.0f * kPi * float(k) / float(sides);
            return c + (u * std::cos(angle) + v * std::sin(angle)) * (r * scale);
        };
        for (int k = 0; k < sides; ++k)
            quad(ring(a, ra, k), ring(a, ra, k + 1), ring(b, rb, k + 1), ring(b, rb, k), TreeMaterial::Bark, SurfacePart::TreeTrunk);
    }

    /// Where a march from `centre + dir * far` towards the centre first meets the crown.
    Vec3f crownPoint(const TreeShapeParams& s, Vec3f centre, Vec3f dir, float far) const {
        float t = 0.0f;
        for (int i = 0; i < 400 && t < far; ++i) {
            const float f = treeCrownDistance(s, centre + dir * (far - t));
            if (f < 1e-3f) break;
            t += f / s.lipschitz;
        }
        return centre + dir * std::fmax(far - t, 0.0f);
    }

    void crown(const TreeShapeParams& s) {
        const Bounds3f box = treeLocalBounds(s);
        // The centre: the ellipsoid's, or a third of the way up a conifer's cone.
        const Vec3f centre = s.conifer ? Vec3f{0, s.crownBase + (s.crownTop - s.crownBase) / 3.0f, 0} : s.crownCentre;
        const float far = length(box.extent()) + 1.0f;
        Vec3f grid[kTreeCrownBands + 1][kTreeCrownSegments];
        for (int b = 0; b <= kTreeCrownBands; ++b)
            for (int k = 0; k < kTreeCrownSegments; ++k) {
                const float polar = kPi * float(b) / kTreeCrownBands, azimuth = 2.0f * kPi * float(k) / kTreeCrownSegments;
                const Vec3f dir{std::sin(polar) * std::cos(azimuth), std::cos(polar), std::sin(polar) * std::sin(azimuth)};
                grid[b][k] = crownPoint(s, centre, dir, far);
            }
        for (int b = 0; b < kTreeCrownBands; ++b)
            for (int k = 0; k < kTreeCrownSegments; ++k) {
                const int k1 = (k + 1) % kTreeCrownSegments;
                const Vec3f a = grid[b][k], c = grid[b + 1][k1], p = grid[b][k1], q = grid[b + 1][k];
                // The poles' bands are fans: one of each quad's triangles has no area there.
                if (b > 0) triangle(a, p, c, TreeMaterial::Leaves, SurfacePart::TreeCrown);
                if (b + 1 < kTreeCrownBands) triangle(a, c, q, TreeMaterial::Leaves, SurfacePart::TreeCrown);
            }
    }
};

} // namespace

size_t meshTree(const TreeRecord& tree, TriangleMesh& mesh) {
    const TreeShapeParams s = treeShapeOf(tree);
    TreeMesher m{tree, mesh};
    m.prism({0, 0, 0}, {0, s.trunkTop, 0}, s.trunkRadius, s.trunkRadius - s.trunkSlope * s.trunkTop, kTreeTrunkSides);
    if (!s.conifer)
        for (int b = 0; b < kTreeBranches; ++b)
            m.prism(s.branchFrom[b], s.branchFrom[b] + s.branchAxis[b], s.branchRadius, s.branchRadius, kTreeBranchSides);
    m.crown(s);
    return m.added;
}

} // namespace urbis
