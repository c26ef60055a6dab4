#include "streets/junction_shapes.h"

#include "streets/polyline.h"
#include "streets/road_fitting.h"
#include "streets/street_network_plane.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

namespace urbis {

namespace {

/// Edges closer to parallel than this sine do not cross (their crossing would be a spike).
constexpr double kMinSine = 0.05;
/// A gap between neighbours within this many radians of a straight line is closed straight across.
constexpr double kStraightGap = 0.05;
/// In a junction, an end's edges run along the chord to the point this far along it (m; at most half
/// the road), so that a bend or a short first segment under the trim does not skew the corners.
constexpr double kChordLength = 10.0;
/// A mitre or a junction's back corner reaches at most this many half widths from the node.
constexpr double kMitreLimit = 4.0;
/// Trims of both ends together leave at least this share of a carriageway.
constexpr double kKeptShare = 0.1;
/// A trim reaches at most this many of the widest corridor halves at its node: crossings of nearly
/// parallel edges farther out are left out (the border runs straight) rather than make a spike.
constexpr double kMaxTrimHalves = 3.0;
/// Junctions merge over a road between them that their trims leave shorter than this (m), however
/// long it is: trims scaled down to fit would leave each junction's border short of its neighbours'
/// edges, and the roads' surfaces over the junctions (where an arterial crosses the grid near one of
/// its junctions, the three junctions' trims overlap).
constexpr double kMinKept = 2.0;
/// A path cut at a carriageway keeps this far from its corridor (m); crossing it at a shallow angle
/// takes at most 1 / kMinPathSine times the corridor.
constexpr double kPathClearance = 0.1, kMinPathSine = 0.35;

/// A road end as its node sees it: pointing away from the node, left = counter-clockwise.
struct NodeEnd {
    uint32_t road = 0;
    bool atEnd = false;         ///< the road's last point is the node
    Vec2d origin;               ///< where it leaves the node, node-relative (not 0 in a merged junction)
    Vec2d d, n;                 ///< unit direction away from the node, and its left
    double angle = 0;
    double length = 0;          ///< of the road, m
    double half = 0;            ///< carriageway half width
    double walkLeft = 0, walkRight = 0;  ///< sidewalk widths, left and right as seen from the node
    std::vector<Vec2d> line;    ///< the centerline from the node outwards
};

/// Where neighbour i's left edge crosses neighbour j's right edge (j follows i counter-clockwise).
struct Gap {
    double angle = 0;           ///< from i to j, counter-clockwise, in (0, 2 pi]
    bool inner = false, outer = false;   ///< crossings of the carriageway edges / sidewalk outer edges
    double s = 0, u = 0;        ///< along i and along j, of the carriageway edges' crossing
    double so = 0, uo = 0;      ///< ... of the sidewalks' outer edges
    bool corner = false;        ///< both sides have a sidewalk: a sidewalk corner joins them
};

struct Node {
    Vec2d point;
    std::vector<NodeEnd> ends;
    std::vector<Gap> gaps;      ///< gap k lies between ends k and k + 1
    bool path = false;
    bool onCarriageway = false; ///< a path node that a carriageway passes through
    double pathTrim = 0;        ///< how far paths are cut back there
};

/// The point `along` m from where end e leaves its node and `offset` m to its left.
Vec2d onEdge(const NodeEnd& e, double along, double offset) { return e.origin + e.d * along + e.n * offset; }

/// Crosses i's left line (offset hi) with j's right line (offset hj), both from the node.
bool crossEdges(const NodeEnd& i, double hi, const NodeEnd& j, double hj, double& s, double& u) {
    return crossLines(onEdge(i, 0, hi), i.d, onEdge(j, 0, -hj), j.d, kMinSine, s, u);
}

/// How far each road is cut back at its first and at its last point (m).
struct Trims {
    std::vector<double> start, end;

    double& of(const NodeEnd& e) { return (e.atEnd ? end : start)[e.road]; }
    double of(const NodeEnd& e) const { return (e.atEnd ? end : start)[e.road]; }
};

/// Sorts a node's ends by angle round it and measures the gaps between neighbours: each end's trim
/// reaches the farthest crossing of its edges with its neighbours' (none at a mitre or a path's cut).
void measureGaps(Node& node, Trims& trims) {
    for (NodeEnd& e : node.ends) {
        if (node.ends.size() >= 3) {
            Vec2d along;
            const Vec2d chord = pointAlong(e.line, std::min(kChordLength, 0.5 * e.length), along) - e.origin;
            if (length(chord) > 0) e.d = chord * (1.0 / length(chord)), e.n = perpLeft(e.d);
        }
        // Sorted by direction: in a merged junction an end may leave 20 m from the middle, and the
        // point 1 m along it would sort by where it leaves, not where it goes.
        const Vec2d ahead = onEdge(e, 1.0 + 4.0 * length(e.origin), 0.0);
        e.angle = std::atan2(ahead.y, ahead.x);
    }
    std::sort(node.ends.begin(), node.ends.end(), [](const NodeEnd& a, const NodeEnd& b) {
        return a.angle != b.angle ? a.angle < b.angle : a.road != b.road ? a.road < b.road : a.atEnd < b.atEnd;
    });
    const size_t count = node.ends.size();
    if (count < 2 || node.onCarriageway) {
        for (const NodeEnd& e : node.ends) trims.of(e) = node.pathTrim;
        return;
    }
    node.gaps.assign(count, {});
    for (size_t k = 0; k < count; ++k) {
        const NodeEnd &i = node.ends[k], &j = node.ends[(k + 1) % count];
        Gap& g = node.gaps[k];
        g.angle = j.angle - i.angle;
        if (g.angle <= 0) g.angle += 2.0 * std::numbers::pi;
        g.corner = i.walkLeft > 0 && j.walkRight > 0;
        g.inner = crossEdges(i, i.half, j, j.half, g.s, g.u);
        if (g.corner) g.outer = crossEdges(i, i.half + i.walkLeft, j, j.half + j.walkRight, g.so, g.uo);
        if (count == 2) continue;   // a mitre: no trim
        // In a junction only crossings ahead of the node count; wider gaps close round its back.
        g.inner = g.inner && g.angle < std::numbers::pi - kStraightGap && g.s >= 0 && g.u >= 0;
        g.outer = g.outer && g.angle < std::numbers::pi - kStraightGap && g.so >= 0 && g.uo >= 0;
        // In a merged junction, neighbours whose edges cross behind where they leave it get no sidewalk
        // corner: its straight border would run over the junction and the lots beside it. Their
        // sidewalks stop with an end face instead.
        if (length(i.origin) + length(j.origin) > 0 && !g.inner && g.angle < std::numbers::pi - kStraightGap)
            g.corner = false;
        double& ti = trims.of(i);
        double& tj = trims.of(j);
        if (g.inner) ti = std::max(ti, g.s), tj = std::max(tj, g.u);
        if (g.outer) ti = std::max(ti, g.so), tj = std::max(tj, g.uo);
        // A sidewalk that no corner continues stops where it would run onto the neighbour's carriageway.
        double s = 0, u = 0;
        const bool ahead = g.angle < std::numbers::pi - kStraightGap;
        if (!g.corner && ahead && i.walkLeft > 0 && crossEdges(i, i.half + i.walkLeft, j, j.half, s, u) && s >= 0 && u >= 0)
            ti = std::max(ti, s);
        if (!g.corner && ahead && j.walkRight > 0 && crossEdges(i, i.half, j, j.half + j.walkRight, s, u) && s >= 0 && u >= 0)
            tj = std::max(tj, u);
    }
    if (count < 3) return;
    double widest = 0;
    for (const NodeEnd& e : node.ends) widest = std::max(widest, e.half + std::max(e.walkLeft, e.walkRight));
    for (const NodeEnd& e : node.ends) {
        double& t = trims.of(e);
        t = std::min(t, kMaxTrimHalves * widest);
    }
}

/// Union-find root of node n.
uint32_t rootOf(std::vector<uint32_t>& parent, uint32_t n) {
    while (parent[n] != n) n = parent[n] = parent[parent[n]];
    return n;
}

float elevationAt(const std::vector<std::vector<float>>& elevations, uint32_t road, bool atEnd) {
    if (road >= elevations.size() || elevations[road].empty()) return 0.0f;
    return atEnd ? elevations[road].back() : elevations[road].front();
}

/// Carriageways through a point: their direction and corridor half width (m), for cutting paths.
struct Corridor {
    Vec2d d;
    double half = 0;
};

/// Junctions closer together than their trims (a short road between two, as where dual carriageways
/// cross) become one: the short roads between them are left out and the others meet round the middle.
void mergeCloseJunctions(const std::vector<Road>& roads, const std::vector<double>& lengths, std::vector<Node>& nodes,
                         const std::unordered_map<PointKey, uint32_t, PointKeyHash>& nodeAt,
                         Trims& trims, std::vector<bool>& consumed) {
    std::vector<uint32_t> parent(nodes.size());
    for (uint32_t n = 0; n < nodes.size(); ++n) parent[n] = n;
    const auto nodesOf = [&](uint32_t r) {
        return std::pair{nodeAt.at(PointKey(roads[r].centerline.front())), nodeAt.at(PointKey(roads[r].centerline.back()))};
    };
    bool merged = false;
    for (uint32_t r = 0; r < roads.size(); ++r) {
        if (consumed[r] || isPath(roads[r].highway)) continue;
        const auto [a, b] = nodesOf(r);
        if (a == b || nodes[a].ends.size() < 3 || nodes[b].ends.size() < 3) continue;
        const double kept = std::min(lengths[r] * (1.0 - kKeptShare), lengths[r] - kMinKept);
        if (trims.start[r] + trims.end[r] <= kept) continue;
        const uint32_t ra = rootOf(parent, a), rb = rootOf(parent, b);
        if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
        merged = true;
    }
    if (!merged) return;
    std::vector<std::vector<uint32_t>> members(nodes.size());
    for (uint32_t n = 0; n < nodes.size(); ++n)
        if (!nodes[n].path) members[rootOf(parent, n)].push_back(n);
    for (uint32_t root = 0; root < nodes.size(); ++root) {
        if (members[root].size() < 2) continue;
        Vec2d centre;
        for (uint32_t m : members[root]) centre = centre + nodes[m].point * (1.0 / double(members[root].size()));
        Node group;
        group.point = centre;
        for (uint32_t m : members[root]) {
            const Vec2d shift = nodes[m].point - centre;
            for (NodeEnd& e : nodes[m].ends) {
                const auto [a, b] = nodesOf(e.road);
                if (rootOf(parent, a) == root && rootOf(parent, b) == root) {
                    consumed[e.road] = true;
                    continue;
                }
                e.origin = shift;
                for (Vec2d& p : e.line) p = p + shift;
                trims.of(e) = 0;
                group.ends.push_back(std::move(e));
            }
            nodes[m].ends.clear();
        }
        measureGaps(group, trims);
        nodes[root] = std::move(group);
    }
}

/// The street graph: the nodes, in the order the roads first reach them, found by point (carriageways'
/// and paths' apart), and the carriageways through each point of their centerlines.
struct StreetGraph {
    std::vector<Node> nodes;
    std::unordered_map<PointKey, uint32_t, PointKeyHash> nodeAt[2];   ///< by isPath
    std::unordered_map<PointKey, std::vector<Corridor>, PointKeyHash> carriagewayAt;
    std::vector<double> lengths;   ///< per road, of its centerline (m)
};

/// Each road's two ends at their nodes; a road with no length is consumed.
StreetGraph collectNodes(const std::vector<Road>& roads, std::vector<bool>& consumed) {
    StreetGraph graph;
    graph.lengths.resize(roads.size());
    for (uint32_t r = 0; r < roads.size(); ++r) {
        const Road& road = roads[r];
        graph.lengths[r] = polylineLength(road.centerline);
        if (road.centerline.size() < 2 || !(graph.lengths[r] > 0)) {
            consumed[r] = true;
            continue;
        }
        const bool path = isPath(road.highway);
        if (!path)
            for (size_t i = 0; i < road.centerline.size(); ++i) {
                const Vec2d a = road.centerline[i == 0 ? 0 : i - 1], b = road.centerline[i == 0 ? 1 : i];
                graph.carriagewayAt[PointKey(road.centerline[i])].push_back(
                    {(b - a) * (1.0 / std::max(length(b - a), 1e-12)),
                     road.width * 0.5 + std::max(road.sidewalkLeftWidth, road.sidewalkRightWidth)});
            }
        for (const bool atEnd : {false, true}) {
            NodeEnd e;
            e.road = r;
            e.atEnd = atEnd;
            e.line = road.centerline;
            if (atEnd) std::reverse(e.line.begin(), e.line.end());
            pointAlong(e.line, 0.0, e.d);
            e.n = perpLeft(e.d);
            e.half = road.width * 0.5;
            e.length = graph.lengths[r];
            e.walkLeft = atEnd ? road.sidewalkRightWidth : road.sidewalkLeftWidth;
            e.walkRight = atEnd ? road.sidewalkLeftWidth : road.sidewalkRightWidth;
            const Vec2d p = e.line.front();
            const auto [it, added] = graph.nodeAt[path].emplace(PointKey(p), uint32_t(graph.nodes.size()));
            if (added) {
                graph.nodes.emplace_back();
                graph.nodes.back().point = p;
                graph.nodes.back().path = path;
            }
            graph.nodes[it->second].ends.push_back(std::move(e));
        }
    }
    return graph;
}

/// Makes a node's lines node-relative (crossings keep their precision), sets how far a path node on a
/// carriageway cuts its paths back, and measures its gaps (measureGaps).
void measureNode(Node& node, const StreetGraph& graph, Trims& trims) {
    for (NodeEnd& e : node.ends)
        for (Vec2d& p : e.line) p = p - node.point;
    if (node.path)
        if (const auto it = graph.carriagewayAt.find(PointKey(node.point)); it != graph.carriagewayAt.end()) {
            node.onCarriageway = true;
            for (const NodeEnd& e : node.ends)
                for (const Corridor& c : it->second) {
                    const double sine = std::max(std::fabs(cross(e.d, c.d)), kMinPathSine);
                    node.pathTrim = std::max(node.pathTrim, c.half / sine + kPathClearance);
                }
        }
    measureGaps(node, trims);
}

/// Scales both trims of a road down to leave some of it (kKeptShare), and writes them to its ends; a
/// path that its cuts eat up is consumed.
void fitTrims(const std::vector<Road>& roads, const std::vector<double>& lengths, Trims& trims, StreetJunctions& out) {
    for (uint32_t r = 0; r < roads.size(); ++r) {
        if (out.consumed[r]) continue;
        const double sum = trims.start[r] + trims.end[r], room = lengths[r] * (1.0 - kKeptShare);
        if (sum > room) {
            if (isPath(roads[r].highway)) out.consumed[r] = true;
            trims.start[r] *= room / sum;
            trims.end[r] *= room / sum;
        }
        out.starts[r].trim = trims.start[r];
        out.ends[r].trim = trims.end[r];
    }
}

/// The corners of a node's trimmed ends as the node sees them (left = counter-clockwise), node-relative,
/// and whether each side's sidewalk goes on round a corner.
struct NodeCorners {
    std::vector<Vec2d> left, right, leftOuter, rightOuter;
    std::vector<bool> leftGoesOn, rightGoesOn;
};

/// Each end's corners where its trim cuts it: square to the road there, or in a junction square to the
/// chord the gaps measured.
NodeCorners trimmedCorners(const Node& node, const Trims& trims) {
    const size_t count = node.ends.size();
    NodeCorners c{std::vector<Vec2d>(count), std::vector<Vec2d>(count), std::vector<Vec2d>(count),
                  std::vector<Vec2d>(count), std::vector<bool>(count, false), std::vector<bool>(count, false)};
    for (size_t k = 0; k < count; ++k) {
        const NodeEnd& e = node.ends[k];
        const double t = trims.of(e);
        Vec2d d;
        Vec2d p = pointAlong(e.line, t, d), n = perpLeft(d);
        if (count >= 3 && !node.onCarriageway) p = onEdge(e, t, 0), n = e.n;   // on the chord the gaps measured
        c.left[k] = p + n * e.half;
        c.right[k] = p - n * e.half;
        c.leftOuter[k] = p + n * (e.half + e.walkLeft);
        c.rightOuter[k] = p - n * (e.half + e.walkRight);
    }
    return c;
}

/// A mitre (a node of two roads): each side's corner is where the two edges cross (capped), shared by
/// both roads.
void mitreCorners(const Node& node, NodeCorners& c) {
    for (size_t k = 0; k < 2; ++k) {
        const size_t j = 1 - k;
        const NodeEnd &a = node.ends[k], &b = node.ends[j];
        const Gap& g = node.gaps[k];
        const double limit = kMitreLimit * std::max(a.half, b.half);
        const auto mitre = [&](bool crossed, double s, double offsetA, double offsetB, double cap) {
            Vec2d p = crossed ? onEdge(a, s, offsetA) : (onEdge(a, 0, offsetA) + onEdge(b, 0, -offsetB)) * 0.5;
            const double l = length(p);
            return l > cap ? p * (cap / l) : p;
        };
        c.left[k] = c.right[j] = mitre(g.inner, g.s, a.half, b.half, limit);
        if (g.corner) {
            c.leftOuter[k] = c.rightOuter[j] =
                mitre(g.outer, g.so, a.half + a.walkLeft, b.half + b.walkRight,
                      kMitreLimit * std::max(a.half + a.walkLeft, b.half + b.walkRight));
            c.leftGoesOn[k] = c.rightGoesOn[j] = true;
        } else {
            c.leftOuter[k] = c.left[k] + a.n * a.walkLeft;
            c.rightOuter[j] = c.right[j] - b.n * b.walkRight;
        }
    }
}

/// The junction polygon of a node of three or more ends, appended to out.junctions, and the sidewalk
/// corners between its neighbours that both have a sidewalk there, appended to out.corners.
void junctionPolygon(const Node& node, const Trims& trims, const std::vector<std::vector<float>>& elevations,
                     NodeCorners& c, StreetJunctions& out) {
    const size_t count = node.ends.size();
    JunctionShape shape;
    shape.centre = node.point;
    shape.path = node.path;
    shape.elevation = elevationAt(elevations, node.ends[0].road, node.ends[0].atEnd);
    double widest = -1;
    for (const NodeEnd& e : node.ends)
        if (e.half > widest) widest = e.half, shape.road = e.road;
    for (size_t k = 0; k < count; ++k) {
        const size_t j = (k + 1) % count;
        const NodeEnd &a = node.ends[k], &b = node.ends[j];
        const Gap& g = node.gaps[k];
        const double ta = trims.of(a), tb = trims.of(b);
        // The border from a's left corner to b's right one: through the crossing when both trims
        // reach it, round the back of the node across a wide gap, else straight.
        std::vector<Vec2d> inner{c.left[k]}, outer{c.leftOuter[k]};
        const double slack = 1e-9 * (1.0 + ta + tb);
        if (g.inner && g.s <= ta + slack && g.u <= tb + slack) inner.push_back(onEdge(a, g.s, a.half));
        const auto back = [&](double offsetA, double offsetB) {
            double s = 0, u = 0;
            Vec2d p = crossEdges(a, offsetA, b, offsetB, s, u) ? onEdge(a, s, offsetA)
                                                             : Vec2d{std::cos(a.angle + g.angle * 0.5),
                                                                     std::sin(a.angle + g.angle * 0.5)} *
                                                                   std::max(offsetA, offsetB);
            const double l = length(p), cap = kMitreLimit * std::max(offsetA, offsetB);
            return l > cap ? p * (cap / l) : p;
        };
        const bool roundBack = g.angle > std::numbers::pi + kStraightGap;
        if (roundBack) inner.push_back(back(a.half, b.half));
        inner.push_back(c.right[j]);
        // The ring: each end's right and left corner, then the border's points between.
        shape.ring.push_back(c.right[k] + node.point);
        for (size_t m = 0; m + 1 < inner.size(); ++m) shape.ring.push_back(inner[m] + node.point);
        if (g.corner) {
            if (g.outer && g.so <= ta + slack && g.uo <= tb + slack)
                outer.push_back(onEdge(a, g.so, a.half + a.walkLeft));
            if (roundBack) outer.push_back(back(a.half + a.walkLeft, b.half + b.walkRight));
            outer.push_back(c.rightOuter[j]);
            SidewalkCorner corner;
            for (const Vec2d& p : inner) corner.inner.push_back(p + node.point);
            for (const Vec2d& p : outer) corner.outer.push_back(p + node.point);
            corner.elevation = shape.elevation;
            corner.road = a.road;
            out.corners.push_back(std::move(corner));
            c.leftGoesOn[k] = c.rightGoesOn[j] = true;
        } else {
            std::vector<Vec2d> side;
            for (const Vec2d& p : inner) side.push_back(p + node.point);
            shape.bareSides.push_back(std::move(side));
        }
    }
    out.junctions.push_back(std::move(shape));
}

/// Each end's RoadEnd from its node's corners, in the road's own frame: the road's own left is the
/// node's right at its last point.
void writeRoadEnds(const Node& node, const NodeCorners& c, StreetJunctions& out) {
    const size_t count = node.ends.size();
    const bool junction = count >= 3 && !node.path && !node.onCarriageway;
    for (size_t k = 0; k < count; ++k) {
        const NodeEnd& e = node.ends[k];
        RoadEnd& end = e.atEnd ? out.ends[e.road] : out.starts[e.road];
        const Vec2d l = c.left[k] + node.point, r = c.right[k] + node.point;
        const Vec2d lo = c.leftOuter[k] + node.point, ro = c.rightOuter[k] + node.point;
        end.left = e.atEnd ? r : l;
        end.right = e.atEnd ? l : r;
        end.leftOuter = e.atEnd ? ro : lo;
        end.rightOuter = e.atEnd ? lo : ro;
        end.leftGoesOn = e.atEnd ? c.rightGoesOn[k] : c.leftGoesOn[k];
        end.rightGoesOn = e.atEnd ? c.leftGoesOn[k] : c.rightGoesOn[k];
        end.deadEnd = count == 1 || node.onCarriageway;
        end.atJunction = junction;
    }
}
} // namespace

Vec2d pointAlong(const std::vector<Vec2d>& line, double distance, Vec2d& direction) {
    direction = {1, 0};
    for (size_t i = 0; i + 1 < line.size(); ++i) {
        const Vec2d ab = line[i + 1] - line[i];
        const double l = length(ab);
        if (!(l > 0)) continue;
        direction = ab * (1.0 / l);
        if (distance <= l || i + 2 == line.size()) return line[i] + direction * std::clamp(distance, 0.0, l);
        distance -= l;
    }
    return line.empty() ? Vec2d{} : line.back();
}

StreetJunctions shapeJunctions(const std::vector<Road>& roads, const std::vector<std::vector<float>>& elevations) {
    StreetJunctions out;
    out.starts.resize(roads.size());
    out.ends.resize(roads.size());
    out.consumed.assign(roads.size(), false);
    StreetGraph graph = collectNodes(roads, out.consumed);
    // Gaps between neighbours and the trims they ask for.
    Trims trims{std::vector<double>(roads.size(), 0), std::vector<double>(roads.size(), 0)};
    for (Node& node : graph.nodes) measureNode(node, graph, trims);
    mergeCloseJunctions(roads, graph.lengths, graph.nodes, graph.nodeAt[0], trims, out.consumed);
    fitTrims(roads, graph.lengths, trims, out);
    for (const Node& node : graph.nodes) {
        NodeCorners corners = trimmedCorners(node, trims);
        const size_t count = node.ends.size();
        if (count == 2 && !node.onCarriageway) mitreCorners(node, corners);
        else if (count >= 3 && !node.onCarriageway) junctionPolygon(node, trims, elevations, corners, out);
        writeRoadEnds(node, corners, out);
    }
    return out;
}

} // namespace urbis
