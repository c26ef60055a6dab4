#include "citygen/facade_layout.h"

#include "geometry/wall_parts.h"
#include "math/hash.h"

#include <algorithm>
#include <cmath>

namespace urbis {

namespace {

constexpr float kEdgeMargin = 0.5f;      ///< solid wall at each end of a wall (the building's corners)
constexpr float kTopMargin = 0.6f;       ///< cornice, or the outside of a parapet
constexpr float kDeckClearance = 0.2f;   ///< between a parapet roof's deck and the top floor's rooms
constexpr float kBottomMargin = 0.3f;    ///< plinth
constexpr float kMinFloorHeight = 2.4f, kMaxFloorHeight = 6.0f;

/// Floors in a grid of `gridHeight` metres: building:levels when tagged and plausible, else by the
/// style's storey height.
int floorCount(const Building& building, const FacadeStyle& style, float gridHeight) {
    const int tagged = building.levels - building.minLevel;
    if (building.levels > 0 && tagged > 0) {
        const float h = gridHeight / float(tagged);
        if (h >= kMinFloorHeight && h <= kMaxFloorHeight) return tagged;
    }
    return std::max(1, int(std::lround(gridHeight / style.floorHeight)));
}

} // namespace

bool layoutWall(const WallContext& context, Vec2d a, Vec2d b, bool outsideRight, float bottom, float top,
                float depthInside, float parapetHeight, uint32_t wallIndex, WallRecord& out) {
    const FacadeStyle& style = context.style;
    const double dx = b.x - a.x, dy = b.y - a.y;
    const float width = float(std::sqrt(dx * dx + dy * dy)), height = top - bottom;
    if (!style.hasFacade || height < kMinFacadeHeight || width < kMinFacadeWidth) return false;
    const float topMargin = std::max(kTopMargin, parapetHeight > 0.0f ? parapetHeight + kDeckClearance : 0.0f);
    const float gridWidth = width - 2.0f * kEdgeMargin, gridHeight = height - topMargin - kBottomMargin;
    const int floors = floorCount(*context.building, style, gridHeight);
    const int slots = std::max(1, int(gridWidth / style.slotWidth));
    if (floors > 0xffff || slots > 0xffff) return false;
    WallRecord w;
    const float ux = float(dx) / width, uy = float(dy) / width;
    const float side = outsideRight ? 1.0f : -1.0f;
    w.origin = Vec3f{float(a.x), bottom, float(-a.y)};
    w.axisU = Vec3f{ux, 0.0f, -uy};
    w.normal = Vec3f{side * uy, 0.0f, side * ux};   // city (uy, -ux) rotated into world (x, -y)
    w.width = width;
    w.height = height;
    w.gridU = kEdgeMargin;
    w.gridV = kBottomMargin;
    w.slots = uint16_t(slots);
    w.floors = uint16_t(floors);
    w.slotWidth = gridWidth / float(slots);
    w.floorHeight = gridHeight / float(floors);
    w.sillHeight = std::min(style.sillHeight, 0.35f * w.floorHeight);
    w.windowHeight = std::clamp(std::min(style.windowHeight, w.floorHeight - w.sillHeight - 0.35f), 0.4f, w.floorHeight);
    w.windowWidth = std::clamp(style.windowFraction * w.slotWidth, 0.4f, w.slotWidth - 0.4f);
    w.reveal = style.reveal;
    w.depthBack = std::clamp(0.4f * depthInside, 0.5f, style.roomDepth);
    w.depthFront = style.style == WallStyle::Curtain ? kMullionDepth : (style.flags & kWallBalconies ? style.balconyDepth : 0.0f);
    w.object = context.object;
    w.wallIndex = wallIndex;
    w.cellSeed = hash2(context.building->seed, wallIndex);
    w.wallMaterial = context.wallMaterial;
    w.facadeMaterials = context.facadeMaterials;
    w.style = style.style;
    w.flags = style.flags;
    w.litChance = context.litChance;
    w.shopLitChance = context.shopLitChance;
    out = w;
    return true;
}

} // namespace urbis
