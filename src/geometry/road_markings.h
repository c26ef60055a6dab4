// Lane markings as a function of where a ray hits a carriageway (host+device): nothing is stored
// per stripe. A Road triangle's RoadSegment says which lines the road carries; forEachMarkingBand
// turns them into bands (lines, rows of lines, dashes) in the segment's coordinates, and the point's
// distance along and across the segment says whether one of them covers it. The export meshes the
// same bands. The layout follows the usual conventions: the Vienna Convention's as most of Europe
// paints them (Germany's RMS, the UK's TSRGD alike in width and rhythm) and, with kMarkAmerican, the
// MUTCD's (part 3).
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

/// One painted line of a segment, or a row of equal lines side by side, in the segment's coordinates
/// (metres along from its start, metres left of its centreline): the one description of where paint
/// lies, which roadPaintAt tests a hit against and the export meshes (export/road_marking_mesh.h).
/// Only its part on the carriageway (|across| <= RoadSegment::halfWidth) is painted.
struct MarkingBand {
    float alongFrom = 0, alongTo = 0;  ///< extent along the segment
    float across = 0;        ///< centre of line `first` of the row
    float pitch = 0;         ///< across, from one line of the row to the next (may be negative)
    int32_t first = 0, last = 0;  ///< the row's lines: across + k * pitch for k in [first, last]
    float halfWidth = 0;     ///< of each line, across
    float dashPeriod = 0;    ///< dashes along the road's distance, one dashLength per period; 0: solid
    float dashLength = 0;
    float roadDistance = 0;  ///< the road's distance at the segment's start (RoadSegment::distance)
    RoadPaint paint = kWhitePaint;

    /// Where dash `n` of the road (counted from the road's start) starts, metres along the segment.
    URBIS_HD float dashStart(float n) const { return n * dashPeriod - roadDistance; }
    /// Whether the point (`along`, `across`) lies on paint of the band.
    URBIS_HD bool covers(float along, float acrossAt) const {
        if (!(along >= alongFrom && along <= alongTo)) return false;
        if (dashPeriod > 0.0f) {
            const float d = roadDistance + along;
            if (!(d - floorf(d / dashPeriod) * dashPeriod < dashLength)) return false;
        }
        const float k = pitch != 0.0f ? fminf(fmaxf(rintf((acrossAt - across) / pitch), float(first)), float(last))
                                      : float(first);
        return withinOf(acrossAt, across + k * pitch, halfWidth);
    }
};

/// A band of one line (`centre`, `halfWidth` across) from `alongFrom` to `alongTo`, solid.
URBIS_HD inline MarkingBand markingLine(float alongFrom, float alongTo, float centre, float halfWidth, RoadPaint paint) {
    MarkingBand b;
    b.alongFrom = alongFrom;
    b.alongTo = alongTo;
    b.across = centre;
    b.halfWidth = halfWidth;
    b.paint = paint;
    return b;
}

/// Calls `visit(const MarkingBand&)` for each band of `s`'s markings, in the order in which they win
/// where they overlap (the centre line, the edge lines, then the rest: all white), until it returns
/// true. The layout follows the usual conventions: traffic keeps right, the forward lanes right of
/// the centre line, unless kMarkLeftHand mirrors them (and the stop lines, which lie across the
/// arriving lanes). Dashes run on the road's distance (RoadSegment::distance + along), so they
/// continue across segments; a zebra paints the half of its band that lies on this segment and the
/// other lines stop at it; nothing is painted beyond the segment.
template <typename Visit>
URBIS_HD inline void forEachMarkingBand(const RoadSegment& s, Visit&& visit) {
    using namespace marking;
    const uint32_t m = s.markings;
    const float hw = s.halfWidth, c = s.centreOffset;
    const bool american = (m & kMarkAmerican) != 0, leftHand = (m & kMarkLeftHand) != 0;

    // Zebra stripes centred on the centreline and every period from it, so that the two segments of
    // a crossing agree whichever way each runs.
    const float zebraHalf = 0.5f * kZebraBand, zebraPeriod = kZebraStripeWidth + kZebraGap;
    const bool zebraStart = (m & kMarkZebraAtStart) != 0, zebraEnd = (m & kMarkZebraAtEnd) != 0;
    const int32_t zebraLines = int32_t(ceilf((hw + 0.5f * kZebraStripeWidth) / zebraPeriod));
    MarkingBand zebra = markingLine(0.0f, zebraHalf, 0.0f, 0.5f * kZebraStripeWidth, kWhitePaint);
    zebra.pitch = zebraPeriod;
    zebra.first = -zebraLines;
    zebra.last = zebraLines;
    if (zebraStart && visit(zebra)) return;
    zebra.alongFrom = s.length - zebraHalf;
    zebra.alongTo = s.length;
    if (zebraEnd && visit(zebra)) return;

    // The other lines run between the zebras.
    const float from = zebraStart ? zebraHalf : 0.0f, to = zebraEnd ? s.length - zebraHalf : s.length;
    const float period = kDashLength + (american ? kDashGapAmericas : kDashGapEurope);
    const auto dashed = [&](MarkingBand b) {
        b.dashPeriod = period;
        b.dashLength = kDashLength;
        b.roadDistance = s.distance;
        return b;
    };

    if (m & kMarkCentreLine) {
        const RoadPaint paint = (m & kMarkCentreYellow) ? kYellowPaint : kWhitePaint;
        MarkingBand centre = markingLine(from, to, c, 0.5f * kLineWidth, paint);
        if (m & kMarkCentreDashed) centre = dashed(centre);
        else if (american) {   // a solid American centre line is doubled
            const float offset = 0.5f * (kDoubleLineGap + kLineWidth);
            centre.across = c - offset;
            centre.pitch = 2.0f * offset;
            centre.last = 1;
        }
        if (visit(centre)) return;
    }

    if (m & kMarkEdgeLines) {
        // A one-way roadway's left edge line is yellow in the Americas (MUTCD 3A.05): the side facing
        // the other direction, its right where traffic keeps left.
        const float edge = hw - kEdgeLineInset - 0.5f * kEdgeLineWidth;
        const bool yellowSide = american && s.lanesBackward == 0;
        const RoadPaint left = yellowSide && !leftHand ? kYellowPaint : kWhitePaint;
        const RoadPaint right = yellowSide && leftHand ? kYellowPaint : kWhitePaint;
        if (visit(markingLine(from, to, edge, 0.5f * kEdgeLineWidth, left))) return;
        if (visit(markingLine(from, to, -edge, 0.5f * kEdgeLineWidth, right))) return;
    }

    // Each side of the centre line: its lanes share its width equally, dashed dividers between them;
    // a stop line across them at the end they arrive at (the forward lanes at the segment's end, the
    // backward ones at its start), behind the zebra where that end has one.
    for (int side = 0; side < 2; ++side) {
        const bool rightSide = side == 0, forward = rightSide != leftHand;
        const float width = rightSide ? c + hw : hw - c, sign = rightSide ? -1.0f : 1.0f;
        const int32_t lanes = int32_t(fmaxf(float(forward ? s.lanesForward : s.lanesBackward), 1.0f));
        if ((m & kMarkLaneDividers) && lanes >= 2) {
            MarkingBand dividers = dashed(markingLine(from, to, c + sign * width / float(lanes), 0.5f * kLineWidth, kWhitePaint));
            dividers.pitch = sign * width / float(lanes);
            dividers.last = lanes - 2;
            if (visit(dividers)) return;
        }
        if (!(m & (forward ? kMarkStopAtEnd : kMarkStopAtStart))) continue;
        const float at = forward ? s.length - kStopLineSetback - (zebraEnd ? zebraHalf : 0.0f) - 0.5f * kStopLineWidth
                                 : kStopLineSetback + (zebraStart ? zebraHalf : 0.0f) + 0.5f * kStopLineWidth;
        const float lo = fmaxf(at - 0.5f * kStopLineWidth, from), hi = fminf(at + 0.5f * kStopLineWidth, to);
        if (visit(markingLine(lo, hi, c + sign * 0.5f * width, 0.5f * width, kWhitePaint))) return;
    }
}

/// The paint at `along` metres from the segment's start and `across` metres left of its centreline
/// (negative: right): the first band of forEachMarkingBand that covers it; none beyond the segment or
/// the carriageway.
URBIS_HD inline RoadPaint roadPaintAt(const RoadSegment& s, float along, float across) {
    if (!(along >= 0.0f && along <= s.length && fabsf(across) <= s.halfWidth)) return kNoPaint;
    RoadPaint paint = kNoPaint;
    forEachMarkingBand(s, [&](const MarkingBand& b) {
        if (!b.covers(along, across)) return false;
        paint = b.paint;
        return true;
    });
    return paint;
}

/// Where a world point lies on a segment: (metres along from its start, metres left of it). World
/// (x, z) with z south, so the left of a direction (dx, dz) is (dz, -dx).
URBIS_HD inline Vec2f roadCoordinates(const RoadSegment& s, float x, float z) {
    const float rx = x - s.start.x, rz = z - s.start.y;
    return {rx * s.direction.x + rz * s.direction.y, rx * s.direction.y - rz * s.direction.x};
}

} // namespace urbis
