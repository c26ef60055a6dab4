// Which ways are drawn at the surface (host): one rule for the roads' fitting, the bridges, the
// railways and the lamps.
#pragma once

namespace urbis {

/// Whether a road or a railway is drawn at the surface at all: the one rule for the roads' fitting,
/// the bridges, the railways and the lamps. A `bridge=yes` way is a deck whatever its other tags (a
/// `layer=-1` bridge spans a valley under a road at layer 0; a covered bridge is still a deck); any
/// other way is not drawn in a tunnel, covered, underground, or below the ground's layer.
template <class Way>
bool atSurface(const Way& w) {
    return w.bridge || (!w.tunnel && !w.covered && !w.underground && w.layer >= 0);
}

} // namespace urbis
