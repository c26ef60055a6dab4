#include "citygen/facade_mesher.h"

#include "citygen/lit_room_palette.h"
#include "geometry/wall_parapet.h"
#include "geometry/wall_parts.h"

namespace urbis {

namespace {

size_t partTriangles(const CellParts& parts) {
    size_t n = 0;
    for (int i = 0; i < parts.count; ++i) n += parts.parts[i].axis == kWallPartBox ? 12 : 2;
    return n;
}

/// The quad of `p` whose normal is `axis`, in the plane `plane`, as two world triangles.
void addQuad(const WallRecord& wall, const WallPart& p, int axis, float plane, TriangleMesh& mesh) {
    const int b = axis == 0 ? 1 : 0, c = axis == 2 ? 1 : 2;
    auto corner = [&](float x, float y) {
        float q[3];
        q[axis] = plane;
        q[b] = x;
        q[c] = y;
        return wall.worldFromWall(q[0], q[1], q[2]);
    };
    const Vec3f p00 = corner(p.lo[b], p.lo[c]), p10 = corner(p.hi[b], p.lo[c]);
    const Vec3f p11 = corner(p.hi[b], p.hi[c]), p01 = corner(p.lo[b], p.hi[c]);
    TriangleInfo info;
    info.material = p.material;
    info.object = wall.object;
    info.part = uint32_t(p.part);
    mesh.add({p00, p10, p11}, info);
    mesh.add({p00, p11, p01}, info);
}

void addParts(const WallRecord& wall, const CellParts& parts, TriangleMesh& mesh) {
    for (int i = 0; i < parts.count; ++i) {
        const WallPart& p = parts.parts[i];
        if (p.axis != kWallPartBox) {
            addQuad(wall, p, p.axis, p.lo[p.axis], mesh);
            continue;
        }
        for (int axis = 0; axis < 3; ++axis) {
            addQuad(wall, p, axis, p.lo[axis], mesh);
            addQuad(wall, p, axis, p.hi[axis], mesh);
        }
    }
}

/// The parapet's top and inner face (wall_parapet.h), two triangles each.
size_t parapetTriangles(const WallRecord& wall) { return wall.parapetHeight > 0.0f ? 4 : 0; }

void addParapet(const WallRecord& wall, TriangleMesh& mesh) {
    if (!parapetTriangles(wall)) return;
    const ParapetTop top = parapetTop(wall);
    Vec3f p[4];
    for (int k = 0; k < 4; ++k) p[k] = wall.worldFromWall(top.corners[k].x, top.corners[k].y, top.corners[k].z);
    TriangleInfo info;
    info.material = wall.wallMaterial;
    info.object = wall.object;
    info.part = uint32_t(SurfacePart::Facade);
    mesh.add({p[0], p[1], p[2]}, info);
    mesh.add({p[0], p[2], p[3]}, info);
    const WallPart inner = parapetInnerFace(wall);
    addQuad(wall, inner, inner.axis, inner.lo[inner.axis], mesh);
}

/// Gives the lit room's parts of cell (floor, slot) its window's palette entry.
void giveLook(const WallRecord& wall, uint32_t floor, uint32_t slot, uint32_t palette, CellParts& cell) {
    const uint32_t lit = wall.facadeMaterials + uint32_t(FacadeMaterial::RoomLit);
    const uint32_t entry = palette + litRoomPaletteEntry(windowLook(wall, floor, slot));
    for (int k = 0; k < cell.count; ++k)
        if (cell.parts[k].material == lit) cell.parts[k].material = entry;
}

} // namespace

size_t wallTwinTriangleCount(const WallRecord& wall) {
    CellParts margins;
    marginParts(wall, margins);
    size_t n = partTriangles(margins) + parapetTriangles(wall);
    for (uint32_t j = 0; j < wall.floors; ++j)
        for (uint32_t i = 0; i < wall.slots; ++i) {
            CellParts cell;
            cellParts(wall, j, i, CellSide::Both, cell);
            n += partTriangles(cell);
        }
    return n;
}

void meshWall(const WallRecord& wall, TriangleMesh& mesh, uint32_t litRoomPalette) {
    CellParts margins;
    marginParts(wall, margins);
    addParts(wall, margins, mesh);
    addParapet(wall, mesh);
    for (uint32_t j = 0; j < wall.floors; ++j)
        for (uint32_t i = 0; i < wall.slots; ++i) {
            CellParts cell;
            cellParts(wall, j, i, CellSide::Both, cell);
            if (litRoomPalette != kNoLitRoomPalette) giveLook(wall, j, i, litRoomPalette, cell);
            addParts(wall, cell, mesh);
        }
}

} // namespace urbis
