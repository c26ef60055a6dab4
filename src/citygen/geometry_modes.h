// Which representation each procedural object kind is rendered with: generated on demand by the
// intersector, or emitted once as stored triangles by the same generator (the triangle twin).
#pragma once

#include <string>

namespace urbis {

enum class Representation : unsigned char { Procedural, Triangles };

/// One representation per kind. Roofs are stored triangles until procedural roofs exist; the
/// choice is kept so that they can follow it then.
struct GeometryModes {
    Representation walls = Representation::Procedural;   ///< facades
    Representation roofs = Representation::Procedural;
};

/// Parses `--geometry`: "procedural" or "triangles" for every kind, or a list of KIND=MODE
/// ("walls=triangles,roofs=procedural"; kinds: walls, roofs; also buildings=MODE for both) over
/// the procedural default. Throws InputError naming the option on anything else.
GeometryModes parseGeometryModes(const std::string& text);

/// "procedural" or "triangles".
const char* representationName(Representation r);

} // namespace urbis
