// Which representation each procedural object kind is rendered with: generated on demand by the
// intersector, or emitted once as stored triangles by the same generator (the triangle twin).
#pragma once

#include <string>

namespace urbis {

/// Plain: no facade at all, each wall a quad of two triangles (a closed mass model: fast previews,
/// and the stored-triangle scenes that other ray tracers can be compared on).
enum class Representation : unsigned char { Procedural, Triangles, Plain };

/// One representation per kind. Of the roofs only flat roofs' parapets are procedural (on the
/// walls' records); decks and the other shapes are stored triangles in every mode.
struct GeometryModes {
    Representation walls = Representation::Procedural;   ///< facades
    Representation roofs = Representation::Procedural;
    Representation lamps = Representation::Procedural;   ///< street lamps: analytic, or their triangle twin (never plain)
    Representation trees = Representation::Procedural;   ///< trees: sphere traced, or their triangle twin (never plain)
};

/// Parses `--geometry`: "procedural", "triangles" or "plain" for every kind, or a list of KIND=MODE
/// ("walls=triangles,roofs=procedural,lamps=triangles"; kinds: walls, roofs, lamps, trees; also
/// buildings=MODE for walls and roofs) over the procedural default; plain lamps and trees are their triangles. Throws InputError naming the option on anything else.
GeometryModes parseGeometryModes(const std::string& text);

/// "procedural", "triangles" or "plain".
const char* representationName(Representation r);

} // namespace urbis
