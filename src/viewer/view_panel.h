// The viewer's panel of scene parameters (Dear ImGui): one widget per key of the scene file, drawn
// by walking visitSceneFields, so that a key added to the scene file appears here with no line of
// its own, and nothing that is not in the scene file does. Only view_window.cpp calls it.
#pragma once

#include "description/scene_description.h"

#include <array>

namespace urbis {

/// What the user did to the panel this frame.
struct PanelEdit {
    bool changed = false;     ///< some value changed (a drag goes on changing it)
    bool committed = false;   ///< an edit is finished: a drag released, a box ticked, a choice made, Enter pressed
};

/// Draws every key of `scene` as a widget in the current ImGui window, sections as tree nodes, and
/// writes the user's edits into `scene`.
PanelEdit drawScenePanel(SceneDescription& scene);

/// Draws the date and the time of day of `scene.astronomy.time` (a slider of local hours that moves
/// the sun through dusk into night). A scene without a time gets one on ticking its box: noon of
/// the summer solstice at the UTC offset of `location`'s longitude (LON, LAT degrees).
PanelEdit drawTimeOfDay(SceneDescription& scene, std::array<double, 2> location);

} // namespace urbis
