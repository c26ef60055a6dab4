// Heights above the ground plane (metres) at which the flat street surfaces lie, lowest first, so that
// surfaces that overlap in plan never share a plane (no surface hides another by rounding).
#pragma once

namespace urbis {

/// Ground cover (landuse, parks, ...): the lowest; areas of higher priority lie higher by kCoverStep.
inline constexpr float kGroundCoverLevel = 0.02f;
inline constexpr float kCoverStep = 0.004f;
/// Water surfaces, over any ground cover.
inline constexpr float kWaterLevel = 0.08f;
/// Paved pedestrian areas and squares.
inline constexpr float kPavedAreaLevel = 0.10f;
/// Footways, paths and cycleways, under the carriageways they cross without a shared node.
inline constexpr float kPathLevel = 0.11f;
/// Carriageways and junctions (one plane: they meet edge to edge and never overlap).
inline constexpr float kRoadLevel = 0.12f;
/// A sidewalk's top: the carriageway plus the curb.
inline constexpr float kCurbHeight = 0.13f;
inline constexpr float kSidewalkLevel = kRoadLevel + kCurbHeight;
/// Rails' ballast bed top, and the rails on it.
inline constexpr float kBallastLevel = 0.30f;

} // namespace urbis
