// --geometry parsing, and what each wall representation puts in the scene.
#include "citygen/city_mesher.h"
#include "scene/geometry_modes.h"
#include "layout/city_layout.h"
#include "base/input_error.h"

#include <gtest/gtest.h>

using namespace urbis;

TEST(GeometryModes, ParsesEveryFormAndRejectsTheRest) {
    GeometryModes all = parseGeometryModes("triangles");
    EXPECT_EQ(all.walls, Representation::Triangles);
    EXPECT_EQ(all.roofs, Representation::Triangles);
    GeometryModes mixed = parseGeometryModes("walls=plain,roofs=procedural");
    EXPECT_EQ(mixed.walls, Representation::Plain);
    EXPECT_EQ(mixed.roofs, Representation::Procedural);
    EXPECT_EQ(parseGeometryModes("buildings=triangles").walls, Representation::Triangles);
    EXPECT_STREQ(representationName(Representation::Plain), "plain");
    EXPECT_THROW(parseGeometryModes("voxels"), InputError);
    EXPECT_THROW(parseGeometryModes("doors=plain"), InputError);
    EXPECT_THROW(parseGeometryModes("walls"), InputError);
}

TEST(GeometryModes, WallRepresentationsDifferAsDocumented) {
    LayoutParams params;
    params.buildings = 60;
    CityModel city = generateCity(params);
    CityMeshOptions procedural, plain, twin;
    plain.geometry.walls = Representation::Plain;
    twin.geometry.walls = Representation::Triangles;
    CityMesh p = meshCity(city, procedural), m = meshCity(city, plain), t = meshCity(city, twin);
    EXPECT_GT(p.walls.size(), 100u);       // facades are records
    EXPECT_TRUE(m.walls.empty());          // the mass model has none
    EXPECT_TRUE(t.walls.empty());          // the twin replaced them by triangles...
    EXPECT_GT(t.mesh.size(), 20 * m.mesh.size());  // ...many more than plain quads
    EXPECT_GT(m.mesh.size(), p.mesh.size());       // plain walls are triangles too
}
