// The two representations of the street lamps render the same: the same object and part at >= 99.9 %
// of pixels (ID AOV), for every head shape on every mount, seen from the street and from below.
#include "cpu/cpu_renderer.h"
#include "integrators/aov_sample.h"
#include "scene/scene.h"
#include "streets/street_lamps.h"
#include "streets/street_materials.h"

#include <gtest/gtest.h>

using namespace urbis;

namespace {

/// Lamps of one head shape on a pole, a bent mast and a wall, 3 m apart along x, leaning to -z.
std::vector<Lamp> lampRow(LampHead head) {
    std::vector<Lamp> lamps;
    const LampMount mounts[] = {LampMount::Pole, LampMount::BentMast, LampMount::Wall};
    for (int i = 0; i < 3; ++i) {
        Lamp l;
        l.position = {3.0 * i, 0.0};
        l.head = head;
        l.mount = mounts[i];
        l.direction = 160.0f + 10.0f * float(i);
        lamps.push_back(l);
    }
    return lamps;
}

Scene sceneOf(const std::vector<Lamp>& lamps, Representation r) {
    StreetOptions options;
    options.lamps = r;
    StreetMesh mesh;
    addLamps(lamps, options, mesh);
    EXPECT_EQ(mesh.counts["lamps"], lamps.size());
    EXPECT_EQ(mesh.lamps.empty(), r != Representation::Procedural);
    Scene scene = Scene::build({.mesh = mesh.mesh, .materials = streetMaterials(),
                                .grounds = {GroundRecord::around(0, 0, 0, uint32_t(StreetMaterial::Sidewalk))},
                                .lamps = mesh.lamps});
    scene.sun = makeSun(35.0f, 200.0f, 0.27f, Vec3f{3.3f, 3.1f, 2.8f});
    return scene;
}

struct IdComparison {
    double same = 0;         ///< fraction of pixels with the same ID
    double lamp = 0;         ///< fraction of pixels that see a lamp
    bool parts[3] = {};      ///< pole, head and glass each seen
};

IdComparison compare(const std::vector<Lamp>& lamps, const Camera& camera) {
    const Scene procedural = sceneOf(lamps, Representation::Procedural);
    const Scene twin = sceneOf(lamps, Representation::Triangles);
    RenderSettings settings;
    settings.width = 320;
    settings.height = 240;
    const std::vector<uint32_t> a = renderIdsCpu(procedural.view(), camera, settings);
    const std::vector<uint32_t> b = renderIdsCpu(twin.view(), camera, settings);
    IdComparison out;
    size_t same = 0, lamp = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        same += a[i] == b[i];
        const uint32_t part = a[i] & ((1u << kSurfacePartBits) - 1u);
        if (a[i] == kSkyId || part < uint32_t(SurfacePart::LampPole)) continue;
        ++lamp;
        out.parts[part - uint32_t(SurfacePart::LampPole)] = true;
    }
    out.same = double(same) / double(a.size());
    out.lamp = double(lamp) / double(a.size());
    return out;
}

} // namespace

TEST(LampTwin, EveryHeadShapeRendersTheSameIds) {
    const float aspect = 320.0f / 240.0f;
    for (LampHead head : {LampHead::Cobra, LampHead::Globe, LampHead::Lantern, LampHead::Cone, LampHead::Flat}) {
        const std::vector<Lamp> row = lampRow(head);
        const Camera street = makeLookAtCamera({3.0f, 1.7f, 7.0f}, {3.0f, 5.0f, 0.0f}, 50.0f, aspect);
        const Camera below = makeLookAtCamera({3.5f, 1.0f, 3.0f}, {3.0f, 6.0f, 0.5f}, 60.0f, aspect);
        bool parts[3] = {};
        for (const Camera& camera : {street, below}) {
            const IdComparison c = compare(row, camera);
            EXPECT_GE(c.same, 0.999) << "head " << int(head);
            EXPECT_GT(c.lamp, 0.005) << "head " << int(head) << ": the view must show the lamps";
            for (int p = 0; p < 3; ++p) parts[p] |= c.parts[p];
        }
        for (int p = 0; p < 3; ++p) EXPECT_TRUE(parts[p]) << "head " << int(head) << " part " << p;
    }
}
