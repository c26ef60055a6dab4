// Lane markings as a function of where a ray hits a carriageway (host+device): nothing is stored
// per stripe. A Road triangle's RoadSegment says which lines the road carries; the point's distance
// along and across the segment says whether one of them covers it. The layout follows the usual
// conventions: the Vienna Convention's as most of Europe paints them (Germany's RMS, the UK's TSRGD
// alike in width and rhythm) and, with kMarkAmerican, the MUTCD's (part 3).
#pragma once

#include "scene/road_segment.h"

#include <cmath>

namespace urbis {

/// Every dimension of the markings, metres: the one place they are written.
namespace marking {
inline constexpr float kLineWidth = 0.12f;         ///< centre lines and lane dividers (EU 0.12, US 4-6 in)
inline constexpr float kDoubleLineGap = 0.12f;     ///< between the two lines of a US double yellow
inline constexpr float kDashLength = 3.0f;         ///< a dash of a broken line (EU and US: 3 m, 10 ft)
inline constexpr float kDashGapEurope = 6.0f;      ///< the gap after it: 3 m / 6 m in built-up areas
inline constexpr float kDashGapAmericas = 9.0f;    ///< 10 ft / 30 ft (MUTCD 3A.06)
inline constexpr float kEdgeLineWidth = 0.15f;
inline constexpr float kEdgeLineInset = 0.20f;     ///< from the carriageway's edge to the edge line
inline constexpr float kStopLineWidth = 0.40f;     ///< along the road (EU 0.5, UK 0.3, US 12-24 in)
inline constexpr float kStopLineSetback = 1.0f;    ///< from the segment's end, or from a zebra's band
inline constexpr float kZebraStripeWidth = 0.5f;   ///< across the road; the stripes run along it
inline constexpr float kZebraGap = 0.5f;
inline constexpr float kZebraBand = 3.0f;          ///< along the road, centred on the crossing's node
} // namespace marking

/// Which paint covers a point of a carriageway: the material is RoadSegment::paint + paint - 1.
enum RoadPaint : uint32_t { kNoPaint = 0, kWhitePaint = 1, kYellowPaint = 2 };

/// Whether `x` lies within `halfWidth` of `centre`.
URBIS_HD inline bool withinOf(float x, float centre, float halfWidth) { return fabsf(x - centre) <= halfWidth; }

/// The paint at `along` metres from the segment's start and `across` metres left of its centreline
/// (negative: right). Traffic keeps right, the forward lanes right of the centre line, unless
/// kMarkLeftHand mirrors them (and the stop lines, which lie across the arriving lanes). Dashes run
/// on the road's distance (RoadSegment::distance + along), so they continue across segments; a zebra
/// paints the half of its band that lies on this segment and hides the other lines there; nothing is
/// painted beyond the segment or the carriageway.
URBIS_HD inline RoadPaint roadPaintAt(const RoadSegment& s, float along, float across) {
    using namespace marking;
    const uint32_t m = s.markings;
    const float hw = s.halfWidth, c = s.centreOffset;
    if (!(along >= 0.0f && along <= s.length && fabsf(across) <= hw)) return kNoPaint;

    const float zebraHalf = 0.5f * kZebraBand;
    const bool zebraStart = (m & kMarkZebraAtStart) != 0, zebraEnd = (m & kMarkZebraAtEnd) != 0;
    if ((zebraStart && along < zebraHalf) || (zebraEnd && along > s.length - zebraHalf)) {
        // Stripes centred on the centreline and every period from it, so that the two segments of a
        // crossing agree whichever way each runs.
        const float period = kZebraStripeWidth + kZebraGap, x = (across + 0.5f * kZebraStripeWidth) / period;
        return x - floorf(x) < kZebraStripeWidth / period ? kWhitePaint : kNoPaint;
    }

    const bool american = (m & kMarkAmerican) != 0;
    const float period = kDashLength + (american ? kDashGapAmericas : kDashGapEurope);
    const float d = s.distance + along;
    const bool dash = d - floorf(d / period) * period < kDashLength;
    const bool leftHand = (m & kMarkLeftHand) != 0;
    const bool forward = (across < c) != leftHand;   // among the forward lanes

    const bool dashed = (m & kMarkCentreDashed) != 0;
    const float centreOffset = !dashed && american ? 0.5f * (kDoubleLineGap + kLineWidth) : 0.0f;
    const bool centre = (m & kMarkCentreLine) && withinOf(fabsf(across - c), centreOffset, 0.5f * kLineWidth) &&
                        (dash || !dashed);

    // Lanes of one direction share its side of the centre line equally, dividers between them: in
    // lane widths from the centre line, at every whole number but 0 and `lanes`.
    const float lanes = fmaxf(float(forward ? s.lanesForward : s.lanesBackward), 1.0f);
    const float side = across < c ? c + hw : hw - c, x = fabsf(across - c) * lanes / side, k = rintf(x);
    const bool divider = (m & kMarkLaneDividers) && dash && k >= 1.0f && k < lanes &&
                         fabsf(x - k) * side <= 0.5f * kLineWidth * lanes;

    const bool edge = (m & kMarkEdgeLines) &&
                      withinOf(fabsf(across), hw - kEdgeLineInset - 0.5f * kEdgeLineWidth, 0.5f * kEdgeLineWidth);
    // A one-way roadway's left edge line is yellow in the Americas (MUTCD 3A.05): the side facing
    // the other direction, its right where traffic keeps left.
    const bool yellowEdge = edge && american && s.lanesBackward == 0 && (across > 0.0f) != leftHand;

    // Stop lines across the lanes arriving at an end: the forward lanes at the end, the backward
    // ones at the start; behind the zebra where the end has one.
    const float stopEnd = s.length - kStopLineSetback - (zebraEnd ? zebraHalf : 0.0f) - 0.5f * kStopLineWidth;
    const float stopStart = kStopLineSetback + (zebraStart ? zebraHalf : 0.0f) + 0.5f * kStopLineWidth;
    const bool stop = (m & (forward ? kMarkStopAtEnd : kMarkStopAtStart)) &&
                      withinOf(along, forward ? stopEnd : stopStart, 0.5f * kStopLineWidth);

    if (centre) return (m & kMarkCentreYellow) ? kYellowPaint : kWhitePaint;
    if (yellowEdge) return kYellowPaint;
    return divider || edge || stop ? kWhitePaint : kNoPaint;
}

/// Where a world point lies on a segment: (metres along from its start, metres left of it). World
/// (x, z) with z south, so the left of a direction (dx, dz) is (dz, -dx).
URBIS_HD inline Vec2f roadCoordinates(const RoadSegment& s, float x, float z) {
    const float rx = x - s.start.x, rz = z - s.start.y;
    return {rx * s.direction.x + rz * s.direction.y, rx * s.direction.y - rz * s.direction.x};
}

} // namespace urbis
