#include "layout/footprint_shapes.h"

#include <algorithm>
#include <array>

namespace urbis {

namespace {

// Gap in metres between a footprint and the sides and back of its lot.
constexpr double kLotGap = 0.5;

// The box (lot coordinates, metres) that the footprint fills.
struct Box {
    double s0, t0, s1, t1;
    double width() const { return s1 - s0; }
    double depth() const { return t1 - t0; }
};

// Probabilities of Courtyard, U, T, L per district (Centre, Middle, Outskirts); the rest is
// Rectangle. A shape that does not fit falls back to the next simpler one.
constexpr std::array<std::array<float, 4>, 3> kShapeChance = {{
    {0.30f, 0.20f, 0.10f, 0.15f},
    {0.10f, 0.15f, 0.15f, 0.20f},
    {0.00f, 0.05f, 0.10f, 0.30f},
}};

bool fits(FootprintShape shape, const Box& b) {
    const double w = b.width(), d = b.depth();
    switch (shape) {
    case FootprintShape::Courtyard: return w >= 20 && d >= 20;
    case FootprintShape::U: return w >= 14 && d >= 12;
    case FootprintShape::T: return w >= 12 && d >= 12;
    case FootprintShape::L: return w >= 8 && d >= 8;
    case FootprintShape::Rectangle: return true;
    }
    return true;
}

FootprintShape chooseShape(District district, const Box& box, HashStream& rng) {
    const auto& chance = kShapeChance[static_cast<int>(district)];
    float u = rng.uniform();
    int pick = 4;  // Rectangle
    for (int i = 0; i < 4; ++i) {
        if (u < chance[static_cast<size_t>(i)]) {
            pick = i;
            break;
        }
        u -= chance[static_cast<size_t>(i)];
    }
    constexpr FootprintShape order[5] = {FootprintShape::Courtyard, FootprintShape::U, FootprintShape::T,
                                         FootprintShape::L, FootprintShape::Rectangle};
    while (!fits(order[pick], box)) ++pick;
    return order[pick];
}

Box buildingBox(const Lot& lot, HashStream& rng) {
    if (lot.wholeBlock) return {0, 0, lot.width, lot.depth};
    Box b{kLotGap, 0, lot.width - kLotGap, lot.depth - kLotGap};
    switch (lot.district) {
    case District::Centre: break;
    case District::Middle:
        b.t0 = rng.uniform(0.0f, 3.0f);
        b.t1 = std::min(b.t1, b.t0 + rng.uniform(12.0f, 22.0f));
        break;
    case District::Outskirts: {
        b.t0 = rng.uniform(3.0f, 6.0f);
        b.t1 = std::min(b.t1, b.t0 + rng.uniform(8.0f, 14.0f));
        // Detached houses: some extra space to either side.
        double spare = std::max(0.0, b.width() - 7.0) * rng.uniform(0.0f, 0.4f);
        double left = spare * rng.uniform();
        b.s0 += left;
        b.s1 -= spare - left;
        break;
    }
    }
    return b;
}

// Rings in lot coordinates, counter-clockwise with s to the right and t up.
Ring rectangle(const Box& b) { return {{b.s0, b.t0}, {b.s1, b.t0}, {b.s1, b.t1}, {b.s0, b.t1}}; }

// The front bar is `front` deep; the wing at the left is `wing` wide; the back right is empty.
Ring lShape(const Box& b, double front, double wing) {
    return {{b.s0, b.t0}, {b.s1, b.t0}, {b.s1, b.t0 + front}, {b.s0 + wing, b.t0 + front},
            {b.s0 + wing, b.t1}, {b.s0, b.t1}};
}

// A front bar `front` deep and a centred stem `stem` wide reaching to the back.
Ring tShape(const Box& b, double front, double stem) {
    const double c = 0.5 * (b.s0 + b.s1), h = 0.5 * stem;
    return {{b.s0, b.t0}, {b.s1, b.t0}, {b.s1, b.t0 + front}, {c + h, b.t0 + front},
            {c + h, b.t1}, {c - h, b.t1}, {c - h, b.t0 + front}, {b.s0, b.t0 + front}};
}

// A front bar `front` deep and two wings `wing` wide reaching to the back.
Ring uShape(const Box& b, double front, double wing) {
    return {{b.s0, b.t0}, {b.s1, b.t0}, {b.s1, b.t1}, {b.s1 - wing, b.t1},
            {b.s1 - wing, b.t0 + front}, {b.s0 + wing, b.t0 + front}, {b.s0 + wing, b.t1}, {b.s0, b.t1}};
}

double clampedShare(double size, HashStream& rng, float lo, float hi, double min, double keep) {
    return std::clamp(size * rng.uniform(lo, hi), min, size - keep);
}

Polygon localPolygon(FootprintShape shape, const Box& b, HashStream& rng) {
    const double w = b.width(), d = b.depth();
    switch (shape) {
    case FootprintShape::Rectangle: return {rectangle(b), {}};
    case FootprintShape::L: {
        Ring r = lShape(b, clampedShare(d, rng, 0.4f, 0.65f, 4, 3), clampedShare(w, rng, 0.35f, 0.6f, 4, 3));
        if (rng.uniform() < 0.5f) {  // mirror: the empty corner at the back left
            for (Vec2d& p : r) p.x = b.s0 + b.s1 - p.x;
            std::reverse(r.begin(), r.end());
        }
        return {std::move(r), {}};
    }
    case FootprintShape::T:
        return {tShape(b, clampedShare(d, rng, 0.35f, 0.6f, 4, 4), clampedShare(w, rng, 0.3f, 0.5f, 4, 4)), {}};
    case FootprintShape::U: {
        double front = clampedShare(d, rng, 0.35f, 0.6f, 5, 4);
        double wing = std::min<double>(rng.uniform(5.0f, 9.0f), 0.5 * (w - 4));
        return {uShape(b, front, wing), {}};
    }
    case FootprintShape::Courtyard: {
        double wing = std::min<double>(rng.uniform(8.0f, 13.0f), 0.5 * (std::min(w, d) - 6));
        Box hole{b.s0 + wing, b.t0 + wing, b.s1 - wing, b.t1 - wing};
        Ring h = rectangle(hole);
        std::reverse(h.begin(), h.end());
        return {rectangle(b), {std::move(h)}};
    }
    }
    return {rectangle(b), {}};
}

} // namespace

Footprint makeFootprint(const Lot& lot, HashStream& rng) {
    const Box box = buildingBox(lot, rng);
    Footprint f;
    f.shape = chooseShape(lot.district, box, rng);
    f.polygon = localPolygon(f.shape, box, rng);
    auto toWorld = [&](Ring& ring) {
        for (Vec2d& p : ring) p = lot.at(p.x, p.y);
    };
    toWorld(f.polygon.outer);
    for (Ring& h : f.polygon.holes) toWorld(h);
    return f;
}

} // namespace urbis
