// How tag readers see an OSM object's tags, apart from libosmium (so tests can fake them).
#pragma once

#include <functional>

namespace urbis {

/// The value of a tag by key, or nullptr when the object lacks the key.
using TagLookup = std::function<const char*(const char* key)>;

} // namespace urbis
