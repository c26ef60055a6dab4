// Which ways are drawn at the surface (host): one rule for the roads' fitting, the bridges, the
// railways and the lamps.
#pragma once

namespace urbis {

/// Whether a road or a railway is drawn at the surface at all: the one rule for the roads' fitting,
/// the bridges, the railways and the lamps. Nothing in a tunnel or underground is. A `bridge=yes` way
/// is a deck whatever its layer (a `layer=-1` bridge spans a valley under a road at layer 0) and
/// whether covered or not (a covered bridge's deck is still there); any other way is not drawn
/// covered or below the ground's layer.
template <class Way>
bool atSurface(const Way& w) {
    return !w.tunnel && !w.underground && (w.bridge || (!w.covered && w.layer >= 0));
}

} // namespace urbis
