#include "app/option_parsing.h"

#include "base/input_error.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>

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
            throw InputError(option + ": '" + text + "' is not a list of numbers separated by '" + separator + "'",
                             FailureKind::Usage);
        values.push_back(v);
        start = end + 1;
    }
    if (values.size() < minCount || values.size() > maxCount)
        throw InputError(option + ": expected " + std::to_string(minCount) +
                         (minCount == maxCount ? "" : " to " + std::to_string(maxCount)) + " numbers, got '" + text + "'",
                         FailureKind::Usage);
    return values;
}

std::optional<std::array<double, 4>> parseBbox(const std::string& text) {
    if (text.empty()) return std::nullopt;
    std::vector<double> b = parseNumberList("--bbox", text, ',', 4, 4);
    if (!(b[0] >= -180 && b[2] <= 180 && b[1] >= -90 && b[3] <= 90 && b[0] < b[2] && b[1] < b[3]))
        throw InputError("--bbox: need MINLON < MAXLON in [-180, 180] and MINLAT < MAXLAT in [-90, 90], got '" + text + "'",
                         FailureKind::Usage);
    return std::array<double, 4>{b[0], b[1], b[2], b[3]};
}

std::array<double, 2> parseLocation(const std::string& option, const std::string& text) {
    std::vector<double> l = parseNumberList(option, text, ',', 2, 2);
    if (!(l[0] >= -180 && l[0] <= 180 && l[1] >= -90 && l[1] <= 90))
        throw InputError(option + ": need LON in [-180, 180] and LAT in [-90, 90] degrees, got '" + text + "'",
                         FailureKind::Usage);
    return {l[0], l[1]};
}

size_t parseMemorySize(const std::string& option, const std::string& text) {
    double number = 0;
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), number);
    std::string unit(ptr, text.data() + text.size());
    for (char& c : unit) c = char(std::toupper(static_cast<unsigned char>(c)));
    const char* const units = "KMGT";
    double scale = 1;
    if (!unit.empty() && std::strchr(units, unit[0])) {
        for (const char* u = units; *u && *u != unit[0]; ++u) scale *= 1024;
        scale *= 1024;
        unit.erase(0, 1);
        if (unit == "IB") unit = "B";
    }
    const bool unitOk = unit.empty() || (unit == "B" && scale > 1);
    const double bytes = number * scale;
    if (ec != std::errc() || ptr == text.data() || !unitOk || !(bytes >= 1) || bytes >= 9.2e18)
        throw InputError(option + ": '" + text + "' is not a memory size (e.g. 8G, 512M, 2000000000)",
                         FailureKind::Usage);
    return size_t(bytes);
}

} // namespace urbis
