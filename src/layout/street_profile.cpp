#include "layout/street_profile.h"

#include <algorithm>

namespace urbis {

namespace {

struct ClassWidths {
    HighwayClass highway;
    float lane, sidewalk;  // m
};
constexpr ClassWidths kWidths[] = {{HighwayClass::Primary, 3.5f, 4.0f},
                                   {HighwayClass::Secondary, 3.25f, 3.5f},
                                   {HighwayClass::Tertiary, 3.25f, 3.0f},
                                   {HighwayClass::Residential, 3.0f, 2.5f}};
constexpr float kNarrowestCarriageway = 3.5f;  // m: a single lane is never narrower

} // namespace

Road StreetProfile::road() const {
    Road r;
    r.highway = highway;
    r.width = width;
    r.lanes = lanes;
    r.lanesForward = oneway ? lanes : (lanes + 1) / 2;
    r.lanesBackward = oneway ? 0 : lanes / 2;
    r.oneway = oneway;
    r.sidewalk = Sidewalk::Both;
    r.sidewalkLeftWidth = r.sidewalkRightWidth = sidewalkWidth;
    r.surface = RoadSurface::Asphalt;
    r.laneMarkings = true;
    r.overtaking = highway != HighwayClass::Primary;
    return r;
}

StreetProfile streetProfile(HighwayClass highway, int lanes, bool oneway) {
    const ClassWidths* w = std::find_if(std::begin(kWidths), std::end(kWidths),
                                        [&](const ClassWidths& c) { return c.highway == highway; });
    if (w == std::end(kWidths)) w = std::end(kWidths) - 1;
    StreetProfile p;
    p.highway = highway;
    p.lanes = lanes;
    p.oneway = oneway;
    p.width = std::max(kNarrowestCarriageway, float(lanes) * w->lane);
    p.sidewalkWidth = w->sidewalk;
    return p;
}

} // namespace urbis
