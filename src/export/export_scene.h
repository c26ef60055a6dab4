// What an export writes, apart from any file format: the triangle twin of a city grouped into named
// nodes (a building each, one per street kind, the ground or terrain), PBR materials, the camera and
// the sun, and the metadata (OSM ids and tags, the origin's lon/lat) that ride along as glTF extras.
#pragma once

#include "math/bounds.h"
#include "math/vec.h"
#include "scene/triangle.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace urbis {

/// A material as glTF's PBR metallic-roughness describes it, with the extensions urbis uses
/// (transmission and ior for glass and water, emissive strength for lit windows and lamps).
struct PbrMaterial {
    std::string name;
    Vec3f baseColour{0.8f, 0.8f, 0.8f};  ///< linear
    float metallic = 0;
    float roughness = 1;                 ///< perceptual: alpha = roughness^2
    float transmission = 0;              ///< KHR_materials_transmission (a thin pane: no volume)
    float ior = 1.5f;                    ///< KHR_materials_ior, where transmission > 0
    Vec3f emission{0, 0, 0};             ///< linear radiance in urbis units (kRadianceUnitCdPerM2)
};

/// Triangles of one material within a node.
struct ExportPrimitive {
    uint32_t material = 0;               ///< index into ExportScene::materials
    std::vector<Triangle> triangles;     ///< world metres: x east, y up, z south (glTF's axes as they are)
};

/// A named piece of the city: one building, or every triangle of a street kind, or the ground.
struct ExportNode {
    std::string name;
    nlohmann::json extras = nlohmann::json::object();  ///< OSM id and tags, or the kind and its count
    std::vector<ExportPrimitive> primitives;           ///< by material, in material order
    bool whole = false;                  ///< a building: one tile takes it whole (else split by triangle)

    size_t triangleCount() const;
    Bounds3f bounds() const;
};

/// The camera of the scene description, in world metres (glTF's camera looks down its local -z).
struct ExportCamera {
    Vec3f position, forward, up;
    float yfovRadians = 0.7f, aspect = 1.0f;
};

struct ExportScene {
    std::vector<PbrMaterial> materials;
    std::vector<ExportNode> nodes;
    std::optional<ExportCamera> camera;
    Vec3f sunDirection{0, 1, 0};         ///< unit, towards the sun
    float sunIrradiance = 0;             ///< on a surface facing it, urbis units; 0: the sun is down
    nlohmann::json extras = nlohmann::json::object();  ///< the asset's: the origin's lon/lat, source, units

    size_t triangleCount() const;
};

/// Luminance (cd/m^2) of one urbis radiance unit: the sun's irradiance 1 is 1e5 lux
/// (description/celestial_parts.h), so radiance 1 is 1e5 / pi cd/m^2.
inline constexpr double kRadianceUnitCdPerM2 = 1.0e5 / 3.14159265358979323846;

} // namespace urbis
