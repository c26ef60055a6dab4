#include "scene/geometry_modes.h"

#include "base/input_error.h"

#include <sstream>

namespace urbis {

namespace {

Representation parseRepresentation(const std::string& text, const std::string& whole) {
    if (text == "procedural") return Representation::Procedural;
    if (text == "triangles") return Representation::Triangles;
    if (text == "plain") return Representation::Plain;
    throw InputError("--geometry: '" + text + "' in '" + whole + "' is not procedural, triangles or plain", FailureKind::Usage);
}

} // namespace

GeometryModes parseGeometryModes(const std::string& text) {
    GeometryModes modes;
    if (text.find('=') == std::string::npos) {
        const Representation r = parseRepresentation(text, text);
        return GeometryModes{r, r, r, r};
    }
    std::stringstream list(text);
    std::string item;
    while (std::getline(list, item, ',')) {
        const size_t eq = item.find('=');
        if (eq == std::string::npos) throw InputError("--geometry: expected KIND=MODE, got '" + item + "'", FailureKind::Usage);
        const std::string kind = item.substr(0, eq);
        const Representation r = parseRepresentation(item.substr(eq + 1), text);
        if (kind == "walls") modes.walls = r;
        else if (kind == "roofs") modes.roofs = r;
        else if (kind == "lamps") modes.lamps = r;
        else if (kind == "trees") modes.trees = r;
        else if (kind == "buildings") modes.walls = modes.roofs = r;
        else throw InputError("--geometry: unknown kind '" + kind + "' (kinds: walls, roofs, lamps, trees, buildings)", FailureKind::Usage);
    }
    return modes;
}

const char* representationName(Representation r) {
    switch (r) {
    case Representation::Procedural: return "procedural";
    case Representation::Triangles: return "triangles";
    case Representation::Plain: return "plain";
    }
    return "?";
}

} // namespace urbis
