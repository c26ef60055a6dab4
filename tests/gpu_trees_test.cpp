// Trees on both backends: rays aimed at a grove hit the same tree at the same distance, bit for bit
// (the sphere tracer and the distance function use urbis.h's exact operations), and the path-traced
// generated city with its trees matches the CPU's image within gpu_render_test's tolerances.
#include "gpu_test_support.h"

#include "citygen/city_mesher.h"
#include "citygen/city_scene.h"
#include "layout/city_layout.h"
#include "scene/camera_framing.h"
#include "tree_test_scenes.h"

using namespace urbis;

TEST(GpuTrees, RaysAtAGroveHitTheSameTreeAtTheSameDistance) {
    URBIS_SKIP_WITHOUT_GPU();
    const Scene scene = test::groveScene(6, false);
    const std::vector<Ray> rays = test::raysBetweenBoxes({-60.0f, 0.5f, -60.0f}, {60.0f, 40.0f, 60.0f}, {-28.0f, 0.0f, -28.0f},
                                                         {28.0f, 12.0f, 28.0f}, 200000, 77u);
    test::expectSameHits(scene, rays, kPrimKindOf<TreeRecord>, "trees", 0.25);
}

TEST(GpuTrees, GeneratedCityWithTreesMatchesTheCpuAt64Spp) {
    URBIS_SKIP_WITHOUT_GPU();
    LayoutParams params;
    params.buildings = 200;
    CityModel city = generateCity(params);
    CityMesh mesh = meshCity(city);
    ASSERT_GT(mesh.trees.size(), 50u);
    Scene scene = buildCityScene(mesh);
    scene.sun = makeSun(35.0f, 140.0f, 0.27f, Vec3f{3.3f, 3.1f, 2.8f});
    RenderSettings settings;
    settings.width = 192;
    settings.height = 128;
    settings.spp = 64;
    settings.seed = 7;
    const Camera camera = frameCity(mesh.cityBounds, 50.0f, float(settings.width) / float(settings.height));
    LinearImage cpu, gpu;
    test::expectParity(test::renderOnBoth(scene, camera, settings, "city with trees", cpu, gpu), 1e-3, 0.01);
}
