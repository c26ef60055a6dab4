#include "astro/civil_time.h"

#include <cmath>
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

double localClockHour(const CivilTime& t) { return t.hour + t.minute / 60.0 + t.second / 3600.0; }

} // namespace urbis
