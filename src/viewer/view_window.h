// The viewer's window (GLFW, Dear ImGui): the picture, the panel of the scene's parameters, the
// overlay and the keys (docs/viewer.md). Built where GLFW and Dear ImGui are found (view_window.cpp);
// elsewhere view_window_none.cpp says so and only --headless runs.
#pragma once

#include "viewer/view_session.h"
#include "viewer/view_script.h"

#include <string>
#include <vector>

namespace urbis {

/// What a windowed run does besides showing the session.
struct ViewWindowOptions {
    std::vector<ScriptStep> script;   ///< steps run before the frame of their number
    uint64_t frames = 0;              ///< the window closes after this many frames; 0: when the user closes it
    std::string windowShot;           ///< PNG of the whole window (picture, panel, overlay) at the end; empty: none
};

/// Why no window can open (built without GLFW and Dear ImGui); empty when one can be tried.
std::string viewerWindowUnavailable();

/// Opens a window the size of the scene's film and runs the session in it until the user closes it,
/// the frames are done or the script quits. Throws InputError (device) when no window opens (no display).
void runViewerWindow(ViewSession& session, const ViewWindowOptions& options);

} // namespace urbis
