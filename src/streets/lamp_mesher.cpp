#include "streets/lamp_mesher.h"

#include "math/constants.h"
#include "scene/lamp_pieces.h"

#include <cmath>

namespace urbis {

namespace {

/// Radius of a regular n-gon with the area of a circle of radius 1.
const float kRingScale = float(std::sqrt(2.0 * kPi / (kLampRingSegments * std::sin(2.0 * kPi / kLampRingSegments))));

struct PieceMesher {
    const LampRecord& lamp;
    const LampPiece& piece;
    TriangleMesh& mesh;
    size_t added = 0;

    void triangle(Vec3f a, Vec3f b, Vec3f c) {
        const TriangleInfo info{lamp.material + uint32_t(piece.material), lamp.object, uint32_t(piece.part)};
        mesh.add({lamp.worldFromLamp(a), lamp.worldFromLamp(b), lamp.worldFromLamp(c)}, info);
        ++added;
    }
    void quad(Vec3f a, Vec3f b, Vec3f c, Vec3f d) {
        triangle(a, b, c);
        triangle(a, c, d);
    }

    /// Point `segment` of the ring at `s` along a frustum's axis, of `radius`, in lamp coordinates.
    Vec3f ringPoint(float s, float radius, int segment) const {
        const float angle = 2.0f * kPi * float(segment) / float(kLampRingSegments);
        const float x = radius * kRingScale * std::cos(angle), z = radius * kRingScale * std::sin(angle);
        Vec3f p = piece.a;
        const int radial = piece.axis == 0 ? 1 : 0;
        p[piece.axis] += s;
        p[radial] += x;
        p.z += z;
        return p;
    }

    void frustum() {
        const float length = piece.b.x, r0 = piece.b.y, r1 = piece.highRadius();
        for (int i = 0; i < kLampRingSegments; ++i) {
            const int j = (i + 1) % kLampRingSegments;
            if (piece.faces & kLampSide) quad(ringPoint(0, r0, i), ringPoint(0, r0, j), ringPoint(length, r1, j), ringPoint(length, r1, i));
            if (piece.faces & kLampCapLow) triangle(ringPoint(0, 0, 0), ringPoint(0, r0, j), ringPoint(0, r0, i));
            if (piece.faces & kLampCapHigh) triangle(ringPoint(length, 0, 0), ringPoint(length, r1, i), ringPoint(length, r1, j));
        }
    }

    /// Latitude bands from the cut plane up to the top; each band's ring scaled as the frustums' are.
    void sphere() {
        const float radius = piece.b.x;
        const float lowest = std::asin(std::fmax(-1.0f, std::fmin(1.0f, (piece.b.y - piece.a.y) / radius)));
        auto point = [&](int band, int segment) {
            const float latitude = lowest + (0.5f * kPi - lowest) * float(band) / float(kLampSphereBands);
            const float angle = 2.0f * kPi * float(segment) / float(kLampRingSegments);
            const float ring = radius * std::cos(latitude) * kRingScale;
            return piece.a + Vec3f{ring * std::cos(angle), radius * std::sin(latitude), ring * std::sin(angle)};
        };
        for (int band = 0; band < kLampSphereBands; ++band)
            for (int i = 0; i < kLampRingSegments; ++i) {
                const int j = (i + 1) % kLampRingSegments;
                if (band + 1 == kLampSphereBands) triangle(point(band, i), point(band, j), point(band + 1, i));
                else quad(point(band, i), point(band, j), point(band + 1, j), point(band + 1, i));
            }
    }
};

} // namespace

size_t meshLamp(const LampRecord& lamp, TriangleMesh& mesh) {
    size_t added = 0;
    for (int i = 0; i < kLampPieces; ++i) {
        const LampPiece piece = lampPiece(lamp, i);
        PieceMesher m{lamp, piece, mesh};
        if (piece.shape == LampPieceShape::Frustum) m.frustum();
        else if (piece.shape == LampPieceShape::Sphere) m.sphere();
        added += m.added;
    }
    return added;
}

} // namespace urbis
