// Multiple importance sampling weights (host+device), Veach 1997, chapter 9.
#pragma once

#include "urbis.h"

namespace urbis {

/// The power heuristic (exponent 2) weight of a sample of strategy f, taken nf times with pdf pf,
/// against strategy g, taken ng times with pdf pg, for the same direction. Where f cannot sample
/// the direction (pf = 0) the weight is 0; where only f can, 1.
URBIS_HD inline float powerHeuristic(float nf, float pf, float ng, float pg) {
    const float f = nf * pf, g = ng * pg;
    if (!(f > 0.0f)) return 0.0f;
    if (!(g > 0.0f)) return 1.0f;
    // A ratio first, so that the squares of large pdfs (the sun's 4e4 per steradian) stay finite.
    const float r = g / f;
    return 1.0f / (1.0f + r * r);
}

} // namespace urbis
