#include "astro/civil_time.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

namespace urbis {

namespace {

/// Reads exactly `digits` decimal digits at `pos` into `value`, advancing `pos`.
bool readDigits(std::string_view text, size_t& pos, int digits, int& value) {
    if (pos + size_t(digits) > text.size()) return false;
    value = 0;
    for (int i = 0; i < digits; ++i) {
        const char c = text[pos + size_t(i)];
        if (c < '0' || c > '9') return false;
        value = value * 10 + (c - '0');
    }
    pos += size_t(digits);
    return true;
}

/// Reads the character `c` at `pos`, advancing `pos`.
bool expect(std::string_view text, size_t& pos, char c) {
    if (pos >= text.size() || text[pos] != c) return false;
    ++pos;
    return true;
}

std::optional<CivilTime> fail(std::string& error, std::string message) {
    error = std::move(message);
    return std::nullopt;
}

} // namespace

int daysInMonth(int year, int month) {
    static constexpr int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
    return month == 2 && leap ? 29 : kDays[month - 1];
}

std::optional<CivilTime> parseIsoTime(std::string_view text, std::string& error) {
    const std::string_view expected = "expected YYYY-MM-DDTHH:MM[:SS] and Z or an offset such as +02:00";
    CivilTime t;
    size_t pos = 0;
    if (!readDigits(text, pos, 4, t.year) || !expect(text, pos, '-') || !readDigits(text, pos, 2, t.month) ||
        !expect(text, pos, '-') || !readDigits(text, pos, 2, t.day))
        return fail(error, std::string(expected));
    if (!expect(text, pos, 'T') || !readDigits(text, pos, 2, t.hour) || !expect(text, pos, ':') ||
        !readDigits(text, pos, 2, t.minute))
        return fail(error, std::string(expected));
    if (pos < text.size() && text[pos] == ':') {
        int whole = 0;
        ++pos;
        if (!readDigits(text, pos, 2, whole)) return fail(error, std::string(expected));
        t.second = whole;
        if (pos < text.size() && (text[pos] == '.' || text[pos] == ',')) {
            ++pos;
            double scale = 0.1;
            const size_t first = pos;
            for (; pos < text.size() && text[pos] >= '0' && text[pos] <= '9'; ++pos, scale *= 0.1)
                t.second += scale * (text[pos] - '0');
            if (pos == first) return fail(error, std::string(expected));
        }
    }
    if (pos == text.size()) return fail(error, "no UTC offset: end with Z or an offset such as +02:00");
    if (text[pos] == 'Z') {
        ++pos;
    } else if (text[pos] == '+' || text[pos] == '-') {
        const int sign = text[pos] == '-' ? -1 : 1;
        ++pos;
        int hours = 0, minutes = 0;
        if (!readDigits(text, pos, 2, hours)) return fail(error, "bad UTC offset: expected +HH:MM, +HHMM or +HH");
        if (pos < text.size()) {
            expect(text, pos, ':');
            if (!readDigits(text, pos, 2, minutes)) return fail(error, "bad UTC offset: expected +HH:MM, +HHMM or +HH");
        }
        if (minutes > 59) return fail(error, "UTC offset minutes " + std::to_string(minutes) + " are not 0..59");
        t.offsetMinutes = sign * (hours * 60 + minutes);
        if (std::abs(t.offsetMinutes) > 14 * 60) return fail(error, "UTC offset beyond +-14:00");
    } else {
        return fail(error, std::string(expected));
    }
    if (pos != text.size()) return fail(error, "unexpected text after the UTC offset");
    if (t.year < 1583) return fail(error, "year " + std::to_string(t.year) + " is before 1583 (the Gregorian calendar)");
    if (t.month < 1 || t.month > 12) return fail(error, "month " + std::to_string(t.month) + " is not 1..12");
    if (t.day < 1 || t.day > daysInMonth(t.year, t.month))
        return fail(error, "day " + std::to_string(t.day) + " is not in " + std::to_string(t.year) + "-" +
                               (t.month < 10 ? "0" : "") + std::to_string(t.month));
    if (t.hour > 23) return fail(error, "hour " + std::to_string(t.hour) + " is not 0..23");
    if (t.minute > 59) return fail(error, "minute " + std::to_string(t.minute) + " is not 0..59");
    if (t.second >= 60.0) return fail(error, "second " + std::to_string(int(t.second)) + " is not 0..59");
    return t;
}

std::string formatIsoTime(const CivilTime& t) {
    char buffer[40];
    const int offset = std::abs(t.offsetMinutes);
    std::snprintf(buffer, sizeof buffer, "%04d-%02d-%02dT%02d:%02d:%02d%c%02d:%02d", t.year, t.month, t.day, t.hour,
                  t.minute, int(t.second), t.offsetMinutes < 0 ? '-' : '+', offset / 60, offset % 60);
    return buffer;
}

double julianDayUtc(const CivilTime& t) {
    // Meeus 7.1 for the Gregorian calendar: January and February count as months 13 and 14 of the
    // year before.
    int y = t.year, m = t.month;
    if (m <= 2) {
        y -= 1;
        m += 12;
    }
    const int a = y / 100, b = 2 - a + a / 4;
    const double dayFraction = (t.hour * 3600.0 + t.minute * 60.0 + t.second - t.offsetMinutes * 60.0) / 86400.0;
    return std::floor(365.25 * (y + 4716)) + std::floor(30.6001 * (m + 1)) + t.day + b - 1524.5 + dayFraction;
}

namespace {

/// Days from 1970-01-01 to a Gregorian date (H. Hinnant, "chrono-Compatible Low-Level Date
/// Algorithms", days_from_civil), and the date of such a day count (civil_from_days).
int64_t daysFromCivil(int64_t y, int m, int d) {
    y -= m <= 2;
    const int64_t era = (y >= 0 ? y : y - 399) / 400;
    const int64_t yoe = y - era * 400;
    const int64_t doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
    const int64_t doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    return era * 146097 + doe - 719468;
}

void civilFromDays(int64_t z, int& year, int& month, int& day) {
    z += 719468;
    const int64_t era = (z >= 0 ? z : z - 146096) / 146097;
    const int64_t doe = z - era * 146097;
    const int64_t yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    const int64_t doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    const int64_t mp = (5 * doy + 2) / 153;
    day = int(doy - (153 * mp + 2) / 5 + 1);
    month = int(mp < 10 ? mp + 3 : mp - 9);
    year = int(yoe + era * 400 + (month <= 2));
}

} // namespace

CivilTime civilTimeAfter(const CivilTime& start, double seconds) {
    const double clock = double(daysFromCivil(start.year, start.month, start.day)) * 86400.0 + start.hour * 3600.0 +
                         start.minute * 60.0 + start.second + seconds;
    const double days = std::floor(clock / 86400.0);
    double rest = clock - days * 86400.0;
    CivilTime t = start;
    civilFromDays(int64_t(days), t.year, t.month, t.day);
    t.hour = std::min(23, int(rest / 3600.0));
    rest -= t.hour * 3600.0;
    t.minute = std::min(59, int(rest / 60.0));
    t.second = std::clamp(rest - t.minute * 60.0, 0.0, std::nextafter(60.0, 0.0));
    return t;
}

double localClockHour(const CivilTime& t) { return t.hour + t.minute / 60.0 + t.second / 3600.0; }

} // namespace urbis
