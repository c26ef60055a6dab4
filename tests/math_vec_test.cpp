#include "math/bounds.h"
#include "math/vec.h"

#include <gtest/gtest.h>

using namespace urbis;

TEST(Vec3f, CrossIsRightHanded) {
    Vec3f z = cross(Vec3f{1, 0, 0}, Vec3f{0, 1, 0});
    EXPECT_FLOAT_EQ(z.z, 1.0f);
    EXPECT_FLOAT_EQ(dot(z, Vec3f{1, 0, 0}), 0.0f);
}

TEST(Bounds3f, AreaOfUnitCubeIsSix) {
    Bounds3f b;
    EXPECT_TRUE(b.empty());
    EXPECT_EQ(b.area(), 0.0f);
    b.extend(Vec3f{0, 0, 0});
    b.extend(Vec3f{1, 1, 1});
    EXPECT_FLOAT_EQ(b.area(), 6.0f);
    EXPECT_EQ(maxAbsAxis(Vec3f{0.1f, -3.0f, 2.0f}), 1);
}
