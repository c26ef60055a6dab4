#include "app/option_parsing.h"

#include "model/input_error.h"

#include <charconv>
#include <cmath>

namespace urbis {

std::vector<double> parseNumberList(const std::string& option, const std::string& text, char separator,
                                    size_t minCount, size_t maxCount) {
    std::vector<double> values;
    size_t start = 0;
    while (start <= text.size()) {
        size_t end = text.find(separator, start);
        if (end == std::string::npos) end = text.size();
        double v = 0;
        const char* first = text.data() + start;
        const char* last = text.data() + end;
        auto [ptr, ec] = std::from_chars(first, last, v);
        if (ec != std::errc() || ptr != last || !std::isfinite(v))
            throw InputError(option + ": '" + text + "' is not a list of numbers separated by '" + separator + "'");
        values.push_back(v);
        start = end + 1;
    }
    if (values.size() < minCount || values.size() > maxCount)
        throw InputError(option + ": expected " + std::to_string(minCount) +
                         (minCount == maxCount ? "" : " to " + std::to_string(maxCount)) + " numbers, got '" + text + "'");
    return values;
}

std::optional<std::array<double, 4>> parseBbox(const std::string& text) {
    if (text.empty()) return std::nullopt;
    std::vector<double> b = parseNumberList("--bbox", text, ',', 4, 4);
    if (!(b[0] >= -180 && b[2] <= 180 && b[1] >= -90 && b[3] <= 90 && b[0] < b[2] && b[1] < b[3]))
        throw InputError("--bbox: need MINLON < MAXLON in [-180, 180] and MINLAT < MAXLAT in [-90, 90], got '" + text + "'");
    return std::array<double, 4>{b[0], b[1], b[2], b[3]};
}

} // namespace urbis
