#include "viewer/place_search.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <unordered_set>

namespace urbis {

namespace {

std::string folded(std::string_view text) {
    std::string out(text);
    std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return out;
}

std::string_view trimmed(std::string_view text) {
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
    return text;
}

} // namespace

std::vector<size_t> findPlaces(const std::vector<NamedPlace>& places, std::string_view query, size_t limit) {
    const std::string q = folded(trimmed(query));
    if (q.empty() || limit == 0) return {};
    std::vector<size_t> groups[3];   // equal, beginning with, holding
    std::unordered_set<std::string_view> seen;
    for (size_t i = 0; i < places.size(); ++i) {
        const std::string name = folded(places[i].name);
        const size_t at = name.find(q);
        if (at == std::string::npos || !seen.insert(places[i].name).second) continue;
        groups[name.size() == q.size() ? 0 : at == 0 ? 1 : 2].push_back(i);
    }
    std::vector<size_t> found;
    for (const std::vector<size_t>& group : groups)
        for (size_t i : group)
            if (found.size() < limit) found.push_back(i);
    return found;
}

} // namespace urbis
