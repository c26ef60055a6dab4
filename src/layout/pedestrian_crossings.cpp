#include "layout/pedestrian_crossings.h"

#include "layout/centerline_edit.h"
#include "math/hash.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <unordered_map>
#include <utility>

namespace urbis {

namespace {

constexpr double kBeyondCorridor = 2.0;   // m from the crossing road's sidewalk to the crossing
constexpr double kShallowestSine = 0.3;   // roads meeting at a slant closer than this get none
constexpr double kDeadEndRoom = 5.0;      // m a crossing stays from a dead end
constexpr double kBetweenCrossings = 4.0; // m between the clearances of consecutive junctions
constexpr double kFromRiver = 25.0;       // m (north-south) from the water: the bridges and their landings
constexpr double kReuseVertex = 0.5;      // m: an existing vertex this close serves as the crossing's

uint32_t pointHash(Vec2d p) {
    const auto x = std::bit_cast<uint64_t>(p.x), y = std::bit_cast<uint64_t>(p.y);
    return hash3(hash2(static_cast<uint32_t>(x), static_cast<uint32_t>(x >> 32)), static_cast<uint32_t>(y),
                 static_cast<uint32_t>(y >> 32));
}

struct PointKey {
    uint64_t x, y;
    bool operator==(const PointKey&) const = default;
};
struct PointKeyHash {
    size_t operator()(const PointKey& k) const { return std::hash<uint64_t>()(k.x * 0x9e3779b97f4a7c15ull ^ k.y); }
};
PointKey keyOf(Vec2d p) { return {std::bit_cast<uint64_t>(p.x), std::bit_cast<uint64_t>(p.y)}; }

struct Visit {
    size_t road, vertex;
};

float chanceOf(HighwayClass c) {
    switch (c) {
    case HighwayClass::Primary: return 0.75f;
    case HighwayClass::Secondary: return 0.6f;
    case HighwayClass::Tertiary: return 0.5f;
    default: return 0.35f;
    }
}

bool major(HighwayClass c) { return c == HighwayClass::Primary || c == HighwayClass::Secondary; }

Vec2d unit(Vec2d from, Vec2d to) {
    const double dx = to.x - from.x, dy = to.y - from.y, len = std::hypot(dx, dy);
    return len > 0 ? Vec2d{dx / len, dy / len} : Vec2d{};
}

class Junctions {
public:
    explicit Junctions(const std::vector<Road>& roads) : roads_(roads) {
        for (size_t r = 0; r < roads.size(); ++r) {
            const std::vector<Vec2d>& c = roads[r].centerline;
            const bool closed = c.size() > 2 && keyOf(c.front()) == keyOf(c.back());
            for (size_t i = 0; i + (closed ? 1 : 0) < c.size(); ++i) visits_[keyOf(c[i])].push_back({r, i});
        }
    }
    /// The other roads' visits of vertex i of road r (none: not a junction).
    std::vector<Visit> others(size_t r, size_t i) const {
        std::vector<Visit> out;
        auto it = visits_.find(keyOf(roads_[r].centerline[i]));
        for (const Visit& v : it->second)
            if (v.road != r) out.push_back(v);
        return out;
    }
    /// Distance in metres along road r from its junction vertex i, toward vertex i + step, that
    /// clears the other roads there (their half carriageway and sidewalk, at the angle they meet);
    /// negative when a road meets it too shallowly for a crossing.
    double clearance(size_t r, size_t i, int step, const std::vector<Visit>& others) const {
        const std::vector<Vec2d>& c = roads_[r].centerline;
        const Vec2d u = unit(c[i], c[i + static_cast<size_t>(step)]);
        double d = 0;
        for (const Visit& v : others) {
            const Road& o = roads_[v.road];
            const std::vector<Vec2d>& oc = o.centerline;
            const size_t a = v.vertex > 0 ? v.vertex - 1 : v.vertex, b = std::min(v.vertex + 1, oc.size() - 1);
            const Vec2d w = unit(oc[a], oc[b]);
            const double sine = std::abs(u.x * w.y - u.y * w.x);
            if (sine < kShallowestSine) return -1;
            const double half = 0.5 * o.width + std::max(o.sidewalkLeftWidth, o.sidewalkRightWidth);
            d = std::max(d, half / sine);
        }
        return d + kBeyondCorridor;
    }

private:
    const std::vector<Road>& roads_;
    std::unordered_map<PointKey, std::vector<Visit>, PointKeyHash> visits_;
};

bool carriesTraffic(HighwayClass c) {
    return c == HighwayClass::Primary || c == HighwayClass::Secondary || c == HighwayClass::Tertiary ||
           c == HighwayClass::Residential;
}

} // namespace

std::vector<Crossing> placeCrossings(std::vector<Road>& roads, uint32_t seed, const River& river) {
    const Junctions junctions(roads);
    const uint32_t key = hash2(seed, 0xc7055u);
    std::vector<std::vector<std::pair<Spot, CrossingKind>>> wanted(roads.size());
    for (size_t r = 0; r < roads.size(); ++r) {
        const Road& road = roads[r];
        if (!carriesTraffic(road.highway)) continue;
        const std::vector<Vec2d>& c = road.centerline;
        std::vector<double> along(c.size(), 0.0);  // m from the start, to compare room with clearances
        for (size_t i = 1; i < c.size(); ++i) along[i] = along[i - 1] + std::hypot(c[i].x - c[i - 1].x, c[i].y - c[i - 1].y);
        const size_t last = c.size() - 1;
        std::vector<std::vector<Visit>> others(c.size());
        for (size_t i = 0; i < c.size(); ++i) others[i] = junctions.others(r, i);
        for (size_t i = 0; i <= last; ++i) {
            if (others[i].empty()) continue;
            for (int step : {-1, 1}) {
                if ((step < 0 && i == 0) || (step > 0 && i == last)) continue;
                const Vec2d toward = c[i + static_cast<size_t>(step)];
                if (hashToUnit(hash3(key, pointHash(c[i]), pointHash(toward))) >= chanceOf(road.highway)) continue;
                const double d = junctions.clearance(r, i, step, others[i]);
                if (d < 0 || river.distance(c[i]) < kFromRiver + d) continue;
                // The room up to the next junction (its own clearance) or dead end.
                size_t j = i + static_cast<size_t>(step);
                while (j != 0 && j != last && others[j].empty()) j += static_cast<size_t>(step);
                double room = std::abs(along[j] - along[i]);
                if (others[j].empty()) room -= kDeadEndRoom;
                else {
                    const double dj = junctions.clearance(r, j, -step, others[j]);
                    if (dj < 0) continue;
                    room -= dj + kBetweenCrossings;
                }
                if (room < d) continue;
                const Spot s = advance(c, {i == last ? last - 1 : i, i == last ? along[last] - along[last - 1] : 0.0}, step * d);
                CrossingKind kind = CrossingKind::Zebra;
                if (road.highway == HighwayClass::Secondary) kind = CrossingKind::Marked;
                if (road.highway == HighwayClass::Primary) {
                    const bool signals = std::any_of(others[i].begin(), others[i].end(),
                                                     [&](const Visit& v) { return major(roads[v.road].highway); });
                    kind = signals ? CrossingKind::TrafficSignals : CrossingKind::Marked;
                }
                wanted[r].push_back({s, kind});
            }
        }
    }
    std::vector<Crossing> out;
    for (size_t r = 0; r < roads.size(); ++r) {
        if (wanted[r].empty()) continue;
        std::sort(wanted[r].begin(), wanted[r].end(), [](const auto& a, const auto& b) {
            return a.first.segment != b.first.segment ? a.first.segment < b.first.segment : a.first.offset < b.first.offset;
        });
        std::vector<Spot> spots;
        for (const auto& w : wanted[r]) spots.push_back(w.first);
        CutCenterline cut = cutAt(roads[r].centerline, spots, kReuseVertex);
        roads[r].centerline = std::move(cut.points);
        for (size_t k = 0; k < spots.size(); ++k) {
            Crossing crossing;
            crossing.position = roads[r].centerline[cut.vertexAt[k]];
            crossing.kind = wanted[r][k].second;
            out.push_back(crossing);
        }
    }
    return out;
}

} // namespace urbis
