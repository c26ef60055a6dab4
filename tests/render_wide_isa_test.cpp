// The CPU's lane tests of the 8-wide BVH (scene/scene_view.h's isa: AVX2 where the CPU has it, SSE
// otherwise) compute the same values bit for bit, so a render is the same image in each: here a
// generated city with procedural facades, lamps and the ground, path traced with the sun.
#include "citygen/city_mesher.h"
#include "citygen/city_scene.h"
#include "cpu/cpu_renderer.h"
#include "layout/city_layout.h"
#include "scene/camera_framing.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

using namespace urbis;

TEST(RenderWideIsa, SameImageForEveryLaneTest) {
    if (hostWideIsa() != WideIsa::Avx2) GTEST_SKIP() << "this CPU has no AVX2: only the SSE lane test runs here";
    LayoutParams params;
    params.buildings = 120;
    params.seed = 5;
    const CityMesh mesh = meshCity(generateCity(params));
    const Scene scene = buildCityScene(mesh);
    ASSERT_GT(scene.walls.size(), 200u);
    RenderSettings settings;
    settings.width = 96;
    settings.height = 64;
    settings.spp = 4;
    const Camera camera = frameCity(mesh.cityBounds, 40.0f, 1.5f);
    auto renderWith = [&](WideIsa isa) {
        SceneView view = scene.view();
        view.isa = isa;
        RenderCounters counters;
        return renderCpu(view, camera, settings, false, counters);
    };
    const LinearImage avx2 = renderWith(WideIsa::Avx2), sse = renderWith(WideIsa::Sse);
    ASSERT_EQ(avx2.pixels.size(), sse.pixels.size());
    size_t differing = 0;
    double sum = 0;
    for (size_t i = 0; i < avx2.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) differing += avx2.pixels[i][c] != sse.pixels[i][c];
        sum += avx2.pixels[i].x;
    }
    EXPECT_EQ(differing, 0u);
    EXPECT_GT(sum, 0.0);   // something was rendered
}
