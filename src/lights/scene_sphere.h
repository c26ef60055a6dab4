// The sphere about a scene that its infinite lights (the sun, the sky, the moon) are measured
// through (host): their power in the light list (lights/light_build.h) and the disk their photons
// leave from (integrators/photon_emission_setup.h) come from this one sphere.
#pragma once

#include "scene/scene.h"

namespace urbis {

/// A sphere, world metres.
struct SceneSphere {
    Vec3f centre;
    float radius = 0;
};

/// The box of what the scene holds that its lights light: its triangles, wall records and lamps. The
/// ground records and the terrain are left out (they reach the world's edge), and so are trees,
/// forests and planets, which stand within a city's box or are lit at their own scale
/// (docs/planets.md). A scene of none of these: the box from (-1, 0, -1) to (1, 1, 1).
Bounds3f lightSceneBounds(const Scene& scene);

/// The sphere about lightSceneBounds: its centre, and half its diagonal, at least 1 m.
SceneSphere lightSceneSphere(const Scene& scene);

} // namespace urbis
