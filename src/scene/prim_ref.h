// A reference from a BVH leaf slot to a primitive of some kind (host+device): the kind in the top
// bits, the index into that kind's array below, dispatched with a switch in the leaf.
#pragma once

#include "urbis.h"

#include <cstdint>

namespace urbis {

/// The primitive kinds a BVH leaf can hold. Roofs and other procedural kinds join here.
enum class PrimKind : uint32_t { Triangle = 0, Wall = 1 };

inline constexpr uint32_t kPrimKindShift = 28;
/// The largest index a reference can carry (2^28 - 1).
inline constexpr uint32_t kPrimIndexMask = (1u << kPrimKindShift) - 1u;

/// The reference to primitive `index` of `kind`.
URBIS_HD inline uint32_t makePrimRef(PrimKind kind, uint32_t index) {
    return (uint32_t(kind) << kPrimKindShift) | (index & kPrimIndexMask);
}
URBIS_HD inline PrimKind primRefKind(uint32_t ref) { return PrimKind(ref >> kPrimKindShift); }
URBIS_HD inline uint32_t primRefIndex(uint32_t ref) { return ref & kPrimIndexMask; }

} // namespace urbis
