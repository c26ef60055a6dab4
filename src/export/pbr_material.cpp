#include "export/pbr_material.h"

#include <cmath>

namespace urbis {

namespace {

/// glTF's perceptual roughness of a normalised Phong lobe of exponent `n`.
float roughnessOfPhong(float n) { return std::sqrt(std::sqrt(2.0f / (n + 2.0f))); }

} // namespace

PbrMaterial pbrMaterialOf(const Material& m, std::string name) {
    PbrMaterial p;
    p.name = std::move(name);
    p.baseColour = m.albedo;
    p.emission = m.emission;
    switch (m.kind) {
    case MaterialKind::Lambertian: break;
    case MaterialKind::Glossy:
        p.roughness = roughnessOfPhong(m.exponent);
        break;
    case MaterialKind::Mirror:
        p.metallic = 1;
        p.roughness = 0;
        break;
    case MaterialKind::Glass:
        p.roughness = 0;
        p.transmission = 1;
        p.ior = m.ior;
        break;
    case MaterialKind::Water:
        p.baseColour = {std::exp(-m.water.absorption.x), std::exp(-m.water.absorption.y), std::exp(-m.water.absorption.z)};
        p.roughness = 0.05f;
        p.transmission = 1;
        p.ior = m.ior;
        break;
    }
    return p;
}

} // namespace urbis
