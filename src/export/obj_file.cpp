#include "export/obj_file.h"

#include "export/welded_mesh.h"
#include "io/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace urbis {

namespace {

/// Writes through `write(FILE*)` to `temporary`; "" or what failed.
template <typename Write>
std::string writeFile(const std::string& temporary, Write write) {
    FILE* f = std::fopen(temporary.c_str(), "wb");
    if (!f) return std::string("cannot write: ") + std::strerror(errno);
    write(f);
    const bool failed = std::ferror(f) != 0;
    const int savedErrno = errno;
    if (std::fclose(f) != 0 || failed) return std::string("cannot write: ") + std::strerror(failed ? savedErrno : errno);
    return "";
}

void writeMtl(FILE* f, const ExportScene& scene) {
    std::fprintf(f, "# urbis: the materials of the OBJ beside it (PBR extension: Pr roughness, Pm metallic)\n");
    for (const PbrMaterial& m : scene.materials) {
        std::fprintf(f, "\nnewmtl %s\nKd %.6g %.6g %.6g\nKe %.6g %.6g %.6g\nPr %.6g\nPm %.6g\n", m.name.c_str(),
                     m.baseColour.x, m.baseColour.y, m.baseColour.z, m.emission.x, m.emission.y, m.emission.z, m.roughness,
                     m.metallic);
        if (m.transmission > 0) std::fprintf(f, "Ni %.6g\nd %.6g\nillum 7\n", m.ior, 1.0f - m.transmission);
    }
}

void writeObj(FILE* f, const ExportScene& scene, const std::string& mtlName) {
    std::fprintf(f, "# urbis: %s\nmtllib %s\n", scene.extras.dump().c_str(), mtlName.c_str());
    size_t firstVertex = 1;
    for (const ExportNode& node : scene.nodes) {
        std::fprintf(f, "o %s\n# extras %s\n", node.name.c_str(), node.extras.dump().c_str());
        for (const ExportPrimitive& p : node.primitives) {
            const WeldedMesh mesh = weldTriangles(p.triangles);
            std::fprintf(f, "usemtl %s\n", scene.materials[p.material].name.c_str());
            for (const Vec3f& v : mesh.positions) std::fprintf(f, "v %.9g %.9g %.9g\n", v.x, v.y, v.z);
            for (size_t i = 0; i < mesh.indices.size(); i += 3)
                std::fprintf(f, "f %zu %zu %zu\n", firstVertex + mesh.indices[i], firstVertex + mesh.indices[i + 1],
                             firstVertex + mesh.indices[i + 2]);
            firstVertex += mesh.positions.size();
        }
    }
}

} // namespace

std::string mtlPathOf(const std::string& objPath) { return std::filesystem::path(objPath).replace_extension(".mtl").string(); }

void writeObjFile(const ExportScene& scene, const std::string& path) {
    const std::string mtl = mtlPathOf(path);
    writeThroughTemporary(mtl, [&](const std::string& t) { return writeFile(t, [&](FILE* f) { writeMtl(f, scene); }); });
    const std::string mtlName = std::filesystem::path(mtl).filename().string();
    writeThroughTemporary(path, [&](const std::string& t) { return writeFile(t, [&](FILE* f) { writeObj(f, scene, mtlName); }); });
}

} // namespace urbis
