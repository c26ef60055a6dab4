// Railways: a ballast bed with two rails per track, rails set flush into the street for trams and
// embedded tracks, and decks (slab, parapets, piers) where a railway is a bridge.
#pragma once

#include "streets/street_mesh.h"

namespace urbis {

/// Rails' profile: a box this wide and high on the ballast, m; embedded rails are strips this wide
/// kEmbeddedRailRise over the carriageway.
inline constexpr float kRailWidth = 0.07f;
inline constexpr float kRailHeight = 0.15f;
inline constexpr float kEmbeddedRailRise = 0.004f;
/// Half the ballast bed's top across one track (at least: wide gauges widen it), and how far its
/// sloped sides reach out beyond the top, m.
inline constexpr double kBallastHalfTop = 1.5;
inline constexpr double kBallastSlopeReach = 0.45;

/// Meshes every railway of `city` drawn at the surface (not tunnel, covered, underground or layer < 0):
/// ballast and rails at the gauge (rail centres gauge / 2 + kRailWidth / 2 off the centerline), or
/// embedded strips for trams and `embedded` tracks; bridges at railwayElevations' heights on a deck.
/// Object ids: options.firstObject + out.objects (after the parts meshed before) + the railway's index.
/// Adds `railways` to out.counts and their triangles to out.trianglesByKind["railways"].
void meshRailways(const CityModel& city, const StreetOptions& options, StreetMesh& out);

} // namespace urbis
