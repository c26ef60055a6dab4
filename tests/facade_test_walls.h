// What the facade tests' hand-made walls share: a punched wall with balconies and shop windows, or
// a curtain wall, on a grid with the usual margins. Each test sets its own frame and grid.
#pragma once

#include "scene/wall_record.h"

namespace urbis::test {

/// Sets everything of `w` but its frame (origin, axes), extent, grid size and identity (object,
/// wall index, seed).
inline void giveTestFacade(WallStyle style, WallRecord& w) {
    w.gridU = 0.5f;
    w.gridV = 0.3f;
    w.sillHeight = 0.9f;
    w.reveal = style == WallStyle::Curtain ? 0.1f : 0.2f;
    w.depthBack = 3.0f;
    w.depthFront = style == WallStyle::Curtain ? 0.12f : 1.2f;
    w.wallMaterial = 1;
    w.facadeMaterials = 2;
    w.style = style;
    w.flags = kWallBalconies | kWallShopFront;
}

} // namespace urbis::test
