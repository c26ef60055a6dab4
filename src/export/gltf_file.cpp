#include "export/gltf_file.h"

#include "export/welded_mesh.h"
#include "io/atomic_file.h"

#include <tiny_gltf.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

namespace urbis {

namespace {

/// nlohmann's JSON as tinygltf's Value (integers beyond int as doubles: exact to 2^53, as JSON readers see them).
tinygltf::Value valueOf(const nlohmann::json& j) {
    if (j.is_object()) {
        tinygltf::Value::Object o;
        for (const auto& [key, v] : j.items()) o[key] = valueOf(v);
        return tinygltf::Value(std::move(o));
    }
    if (j.is_array()) {
        tinygltf::Value::Array a;
        for (const auto& v : j) a.push_back(valueOf(v));
        return tinygltf::Value(std::move(a));
    }
    if (j.is_boolean()) return tinygltf::Value(j.get<bool>());
    if (j.is_number_integer()) {
        const int64_t v = j.get<int64_t>();
        if (v >= std::numeric_limits<int>::min() && v <= std::numeric_limits<int>::max()) return tinygltf::Value(int(v));
        return tinygltf::Value(double(v));
    }
    if (j.is_number()) return tinygltf::Value(j.get<double>());
    if (j.is_string()) return tinygltf::Value(j.get<std::string>());
    return tinygltf::Value();
}

/// Appends `count` elements of `type` and `componentType` (`bytes` of them, 4-byte aligned: every
/// element is) to the model's only buffer as a view of `target` and an accessor; its index.
int addAccessor(tinygltf::Model& model, const void* bytes, size_t size, int target, int componentType, size_t count,
                int type) {
    std::vector<unsigned char>& data = model.buffers[0].data;
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = size;
    view.target = target;
    data.insert(data.end(), static_cast<const unsigned char*>(bytes), static_cast<const unsigned char*>(bytes) + size);
    model.bufferViews.push_back(view);
    tinygltf::Accessor accessor;
    accessor.bufferView = int(model.bufferViews.size() - 1);
    accessor.componentType = componentType;
    accessor.count = count;
    accessor.type = type;
    model.accessors.push_back(accessor);
    return int(model.accessors.size() - 1);
}

tinygltf::Primitive primitiveOf(tinygltf::Model& model, const ExportPrimitive& p) {
    const WeldedMesh mesh = weldTriangles(p.triangles);
    tinygltf::Primitive primitive;
    const int positions = addAccessor(model, mesh.positions.data(), mesh.positions.size() * sizeof(Vec3f),
                                      TINYGLTF_TARGET_ARRAY_BUFFER, TINYGLTF_COMPONENT_TYPE_FLOAT, mesh.positions.size(),
                                      TINYGLTF_TYPE_VEC3);
    model.accessors[size_t(positions)].minValues = {mesh.lo.x, mesh.lo.y, mesh.lo.z};
    model.accessors[size_t(positions)].maxValues = {mesh.hi.x, mesh.hi.y, mesh.hi.z};
    primitive.attributes["POSITION"] = positions;
    primitive.indices = addAccessor(model, mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t),
                                    TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                                    mesh.indices.size(), TINYGLTF_TYPE_SCALAR);
    primitive.material = int(p.material);
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    return primitive;
}

tinygltf::Material materialOf(const PbrMaterial& m, std::vector<std::string>& extensionsUsed) {
    const auto use = [&](const std::string& name) {
        if (std::find(extensionsUsed.begin(), extensionsUsed.end(), name) == extensionsUsed.end()) extensionsUsed.push_back(name);
    };
    tinygltf::Material g;
    g.name = m.name;
    g.doubleSided = true;  // urbis's surfaces reflect and emit on both sides
    g.pbrMetallicRoughness.baseColorFactor = {m.baseColour.x, m.baseColour.y, m.baseColour.z, 1.0};
    g.pbrMetallicRoughness.metallicFactor = m.metallic;
    g.pbrMetallicRoughness.roughnessFactor = m.roughness;
    const float strength = std::fmax(m.emission.x, std::fmax(m.emission.y, m.emission.z));
    if (strength > 0) {
        g.emissiveFactor = {m.emission.x / strength, m.emission.y / strength, m.emission.z / strength};
        g.extensions["KHR_materials_emissive_strength"] =
            tinygltf::Value(tinygltf::Value::Object{{"emissiveStrength", tinygltf::Value(double(strength))}});
        use("KHR_materials_emissive_strength");
    }
    if (m.transmission > 0) {
        g.extensions["KHR_materials_transmission"] =
            tinygltf::Value(tinygltf::Value::Object{{"transmissionFactor", tinygltf::Value(double(m.transmission))}});
        g.extensions["KHR_materials_ior"] = tinygltf::Value(tinygltf::Value::Object{{"ior", tinygltf::Value(double(m.ior))}});
        use("KHR_materials_transmission");
        use("KHR_materials_ior");
    }
    return g;
}

/// The rotation (x, y, z, w) whose matrix has columns `x`, `y`, `z` (orthonormal, right-handed).
std::vector<double> quaternionOfBasis(Vec3f x, Vec3f y, Vec3f z) {
    const double trace = double(x.x) + y.y + z.z;
    double qx, qy, qz, qw;
    if (trace > 0) {
        const double s = 0.5 / std::sqrt(trace + 1.0);
        qw = 0.25 / s, qx = (y.z - z.y) * s, qy = (z.x - x.z) * s, qz = (x.y - y.x) * s;
    } else if (x.x > y.y && x.x > z.z) {
        const double s = 2.0 * std::sqrt(1.0 + x.x - y.y - z.z);
        qw = (y.z - z.y) / s, qx = 0.25 * s, qy = (y.x + x.y) / s, qz = (z.x + x.z) / s;
    } else if (y.y > z.z) {
        const double s = 2.0 * std::sqrt(1.0 + y.y - x.x - z.z);
        qw = (z.x - x.z) / s, qx = (y.x + x.y) / s, qy = 0.25 * s, qz = (z.y + y.z) / s;
    } else {
        const double s = 2.0 * std::sqrt(1.0 + z.z - x.x - y.y);
        qw = (x.y - y.x) / s, qx = (z.x + x.z) / s, qy = (z.y + y.z) / s, qz = 0.25 * s;
    }
    const double n = std::sqrt(qx * qx + qy * qy + qz * qz + qw * qw);
    return {qx / n, qy / n, qz / n, qw / n};
}

/// The node of a camera or light looking along `forward` (its local -z) with `up` near its local +y.
tinygltf::Node lookingNode(const std::string& name, Vec3f position, Vec3f forward, Vec3f up) {
    const Vec3f z = normalize(forward * -1.0f);
    const Vec3f x = normalize(cross(up, z));
    const Vec3f y = cross(z, x);
    tinygltf::Node node;
    node.name = name;
    node.translation = {position.x, position.y, position.z};
    node.rotation = quaternionOfBasis(x, y, z);
    return node;
}

tinygltf::Model modelOf(const ExportScene& scene) {
    tinygltf::Model model;
    model.asset.generator = "urbis";
    model.asset.extras = valueOf(scene.extras);
    model.buffers.resize(1);
    for (const PbrMaterial& m : scene.materials) model.materials.push_back(materialOf(m, model.extensionsUsed));
    tinygltf::Scene root;
    root.name = "city";
    for (const ExportNode& n : scene.nodes) {
        tinygltf::Mesh mesh;
        mesh.name = n.name;
        for (const ExportPrimitive& p : n.primitives) mesh.primitives.push_back(primitiveOf(model, p));
        model.meshes.push_back(std::move(mesh));
        tinygltf::Node node;
        node.name = n.name;
        node.mesh = int(model.meshes.size() - 1);
        node.extras = valueOf(n.extras);
        root.nodes.push_back(int(model.nodes.size()));
        model.nodes.push_back(std::move(node));
    }
    if (scene.camera) {
        const ExportCamera& c = *scene.camera;
        tinygltf::Camera camera;
        camera.name = "camera";
        camera.type = "perspective";
        camera.perspective.yfov = c.yfovRadians;
        camera.perspective.aspectRatio = c.aspect;
        camera.perspective.znear = 0.1;
        camera.perspective.zfar = 1.0e6;  // tinygltf writes a zfar of 0, which glTF refuses, rather than none
        model.cameras.push_back(camera);
        tinygltf::Node node = lookingNode("camera", c.position, c.forward, c.up);
        node.camera = 0;
        root.nodes.push_back(int(model.nodes.size()));
        model.nodes.push_back(std::move(node));
    }
    if (scene.sunIrradiance > 0) {
        tinygltf::Light sun;
        sun.name = "sun";
        sun.type = "directional";
        sun.color = {1.0, 1.0, 1.0};
        sun.intensity = scene.sunIrradiance * kRadianceUnitCdPerM2 * 3.14159265358979323846;  // lux
        model.lights.push_back(sun);
        const Vec3f d = scene.sunDirection;
        const Vec3f up = std::fabs(d.y) > 0.99f ? Vec3f{0, 0, -1} : Vec3f{0, 1, 0};
        tinygltf::Node node = lookingNode("sun", d * 1000.0f, d * -1.0f, up);
        node.extensions["KHR_lights_punctual"] = tinygltf::Value(tinygltf::Value::Object{{"light", tinygltf::Value(0)}});
        root.nodes.push_back(int(model.nodes.size()));
        model.nodes.push_back(std::move(node));
    }
    model.scenes.push_back(std::move(root));
    model.defaultScene = 0;
    return model;
}

} // namespace

void writeGltfFile(const ExportScene& scene, const std::string& path, bool binary) {
    const tinygltf::Model model = modelOf(scene);
    writeThroughTemporary(path, [&](const std::string& temporary) -> std::string {
        std::ofstream out(temporary, std::ios::binary);
        if (!out) return std::string("cannot write: ") + std::strerror(errno);
        tinygltf::TinyGLTF gltf;
        if (!gltf.WriteGltfSceneToStream(&model, out, !binary, binary)) return "cannot write the glTF";
        out.close();
        return out ? "" : std::string("cannot write: ") + std::strerror(errno);
    });
}

} // namespace urbis
