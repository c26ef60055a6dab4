#include "streets/bridge_spans.h"

#include "streets/road_elevation.h"

#include <algorithm>
#include <optional>
#include <unordered_map>

namespace urbis {

std::vector<BridgeSpan> bridgeSpans(const std::vector<BridgeWay>& ways) {
    // End e of way w is 2w (its first point) or 2w + 1 (its last).
    auto pointOf = [&](size_t end) { return end % 2 ? ways[end / 2].line->back() : ways[end / 2].line->front(); };
    std::unordered_map<PointKey, std::vector<size_t>, PointKeyHash> endsAt;
    for (size_t w = 0; w < ways.size(); ++w)
        for (size_t end : {2 * w, 2 * w + 1}) endsAt[keyOf(pointOf(end))].push_back(end);
    // The one other end at the same point, or none (the chain stops there).
    auto partner = [&](size_t end) -> std::optional<size_t> {
        const std::vector<size_t>& at = endsAt.at(keyOf(pointOf(end)));
        if (at.size() != 2) return std::nullopt;
        return at[0] == end ? at[1] : at[0];
    };
    std::vector<uint8_t> visited(ways.size(), 0);
    std::vector<BridgeSpan> spans;
    auto walk = [&](size_t end) {
        BridgeSpan span;
        for (;;) {
            const size_t w = end / 2;
            if (visited[w]) break;
            visited[w] = 1;
            std::vector<Vec2d> line = *ways[w].line;
            std::vector<float> elevation = *ways[w].elevation;
            if (end % 2) {  // entered at its last point: run it backwards
                std::reverse(line.begin(), line.end());
                std::reverse(elevation.begin(), elevation.end());
            }
            for (size_t i = span.line.empty() ? 0 : 1; i < line.size(); ++i) {
                span.line.push_back({line[i].x, -line[i].y});
                span.elevation.push_back(elevation[i]);
            }
            span.halfWidth = std::max(span.halfWidth, ways[w].halfWidth);
            const std::optional<size_t> next = partner(end ^ 1);
            if (!next) break;
            end = *next;
        }
        if (span.line.size() >= 2) spans.push_back(std::move(span));
    };
    for (size_t w = 0; w < ways.size(); ++w)
        for (size_t end : {2 * w, 2 * w + 1})
            if (!visited[w] && !partner(end)) walk(end);
    for (size_t w = 0; w < ways.size(); ++w)
        if (!visited[w]) walk(2 * w);  // rings
    return spans;
}

} // namespace urbis
