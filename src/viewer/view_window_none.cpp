// The viewer's window where urbis was built without GLFW and Dear ImGui (CMakeLists.txt picks this
// file or view_window.cpp).
#include "viewer/view_window.h"

#include "base/input_error.h"

namespace urbis {

std::string viewerWindowUnavailable() {
    return "urbis was built without the viewer's window (GLFW and Dear ImGui: scripts/install-deps.sh installs them); "
           "--headless runs without one";
}

void runViewerWindow(ViewSession&, const ViewWindowOptions&) {
    throw InputError("view: " + viewerWindowUnavailable(), FailureKind::Usage);
}

} // namespace urbis
