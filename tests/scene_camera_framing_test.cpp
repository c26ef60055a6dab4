// frameCity: every corner of the city's bounds (or of its pieces) projects inside the image, whatever its shape.
#include "scene/camera_framing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace urbis;

namespace {

struct FilmPoint {
    float sx, sy, depth;
};

/// Where world point `p` lands on the film, the inverse of Camera::generateRay: (sx, sy) in
/// [0,1]^2 when inside the image, and its depth along the view direction.
FilmPoint project(const Camera& camera, Vec3f p) {
    const Vec3f q = p - camera.position;
    const float depth = dot(q, camera.forward);
    const float px = dot(q, camera.right) / depth, py = dot(q, camera.up) / depth;
    return {0.5f * (px / (camera.tanHalfFovY * camera.aspect) + 1.0f), 0.5f * (1.0f - py / camera.tanHalfFovY), depth};
}

/// The corners' film bounding box: {min sx, min sy, max sx, max sy}.
std::array<float, 4> projectedBox(const Camera& camera, const Bounds3f& b) {
    std::array<float, 4> box{1e30f, 1e30f, -1e30f, -1e30f};
    for (int i = 0; i < 8; ++i) {
        const FilmPoint f = project(camera, {i & 1 ? b.hi.x : b.lo.x, i & 2 ? b.hi.y : b.lo.y, i & 4 ? b.hi.z : b.lo.z});
        EXPECT_GT(f.depth, 0.0f) << "a corner behind the camera";
        box = {std::min(box[0], f.sx), std::min(box[1], f.sy), std::max(box[2], f.sx), std::max(box[3], f.sy)};
    }
    return box;
}

} // namespace

TEST(CameraFraming, ProjectionInvertsGenerateRay) {
    const Camera camera = makeLookAtCamera({10, 50, 80}, {0, 5, 0}, 50.0f, 16.0f / 9.0f);
    const Ray ray = camera.generateRay(0.2f, 0.7f);
    const FilmPoint f = project(camera, ray.origin + ray.dir * 37.0f);
    EXPECT_NEAR(f.sx, 0.2f, 1e-4f);
    EXPECT_NEAR(f.sy, 0.7f, 1e-4f);
}

TEST(CameraFraming, EveryCornerInsideTheImageForAnyShapeFovAndAspect) {
    const Bounds3f shapes[] = {
        {{-50, 0, -50}, {50, 20, 50}},           // the default when empty
        {{-4000, 0, -60}, {4000, 30, 60}},       // long and thin, east-west
        {{-60, 0, -4000}, {60, 30, 4000}},       // long and thin, north-south
        {{-20, 0, -20}, {20, 500, 20}},          // one tall tower
        {{-3000, 0, -3000}, {3000, 5, 3000}},    // wide and flat
        {{1200, 0, -900}, {2200, 140, 300}},     // off the origin
    };
    for (const Bounds3f& b : shapes)
        for (float fov : {20.0f, 50.0f, 90.0f, 150.0f})
            for (float aspect : {0.25f, 1.0f, 16.0f / 9.0f, 4.0f}) {
                const std::array<float, 4> box = projectedBox(frameCity(b, fov, aspect), b);
                SCOPED_TRACE(::testing::Message() << "fov " << fov << " aspect " << aspect << " box " << b.lo.x << ","
                                                  << b.lo.z << " .. " << b.hi.x << "," << b.hi.y << "," << b.hi.z);
                // The corners sit on the margin, up to float rounding over boxes of 8 km.
                const float inset = 0.5f * kFramingMargin - 2e-3f;
                EXPECT_GE(box[0], inset);
                EXPECT_GE(box[1], inset);
                EXPECT_LE(box[2], 1.0f - inset);
                EXPECT_LE(box[3], 1.0f - inset);
            }
}

TEST(CameraFraming, TheCityFillsTheFrameOnOneAxis) {
    const Bounds3f b{{-800, 0, -500}, {700, 60, 400}};
    for (float aspect : {0.5f, 16.0f / 9.0f, 3.0f}) {
        const std::array<float, 4> box = projectedBox(frameCity(b, 50.0f, aspect), b);
        // The least distance puts corners on both margins of one axis: it spans the image less the margins.
        const float span = std::max(box[2] - box[0], box[3] - box[1]);
        EXPECT_GT(span, 0.95f) << "aspect " << aspect << ": the city is framed too small";
        EXPECT_NEAR(box[0] + box[2], 1.0f, 1e-3f) << "not centred across";
        EXPECT_NEAR(box[1] + box[3], 1.0f, 1e-3f) << "not centred up and down";
    }
}

TEST(CameraFraming, PiecesCentreTheCityItselfNotItsBox) {
    // An L of low blocks around an empty near (south-west) quarter, a tower at its far end: the one box's
    // near bottom corner holds no building, and framing the box leaves the city off-centre.
    const Bounds3f pieces[] = {{{-1000, 0, -1000}, {1000, 20, -800}},
                               {{800, 0, -1000}, {1000, 20, 1000}},
                               {{900, 0, -1000}, {1000, 300, -900}}};
    Bounds3f all;
    for (const Bounds3f& p : pieces) all.extend(p);
    // The film box of all the pieces' corners under a camera.
    const auto filmBox = [&pieces](const Camera& camera) {
        std::array<float, 4> film{1e30f, 1e30f, -1e30f, -1e30f};
        for (const Bounds3f& p : pieces) {
            const std::array<float, 4> box = projectedBox(camera, p);
            film = {std::min(film[0], box[0]), std::min(film[1], box[1]), std::max(film[2], box[2]),
                    std::max(film[3], box[3])};
        }
        return film;
    };
    for (float aspect : {0.75f, 16.0f / 9.0f}) {
        SCOPED_TRACE(::testing::Message() << "aspect " << aspect);
        const std::array<float, 4> tight = filmBox(frameCity(pieces, 50.0f, aspect));
        EXPECT_NEAR(tight[0] + tight[2], 1.0f, 1e-3f);
        EXPECT_NEAR(tight[1] + tight[3], 1.0f, 1e-3f);
        EXPECT_GT(std::max(tight[2] - tight[0], tight[3] - tight[1]), 0.95f) << "framed too small";
        const std::array<float, 4> loose = filmBox(frameCity(all, 50.0f, aspect));
        EXPECT_GT(std::abs(loose[1] + loose[3] - 1.0f), 0.05f) << "the box alone would frame this city as well";
    }
}
