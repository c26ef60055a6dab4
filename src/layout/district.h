// Districts of a generated city: rings around the centre that set lot sizes, shapes and uses.
#pragma once

#include <cstdint>

namespace urbis {

enum class District : uint8_t { Centre, Middle, Outskirts };

/// The district at a distance from the centre, given as a fraction of the city radius.
inline District districtAt(double normalisedRadius) {
    if (normalisedRadius < 0.3) return District::Centre;
    return normalisedRadius < 0.65 ? District::Middle : District::Outskirts;
}

} // namespace urbis
