// Surface materials (host+device POD). Lambertian only for now; the kind tag leaves room for
// glossy, mirror and glass without changing the record's users.
#pragma once

#include "math/vec.h"

#include <cstdint>

namespace urbis {

enum class MaterialKind : uint32_t { Lambertian };

struct Material {
    Vec3f albedo{0.8f, 0.8f, 0.8f};  ///< linear reflectance in [0, 1)
    MaterialKind kind = MaterialKind::Lambertian;
};

} // namespace urbis
