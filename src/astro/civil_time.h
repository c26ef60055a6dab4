// A moment as people write it: an ISO 8601 date and clock time with its offset from UTC
// (`2024-06-21T20:30+02:00`, `2024-06-21T18:30:00Z`), and the Julian day of the same instant, which
// the ephemerides of astro/ take. Host only.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace urbis {

/// A date and time on the local clock of a place whose clock runs `offsetMinutes` ahead of UTC.
struct CivilTime {
    int year = 2000, month = 1, day = 1;   ///< Gregorian calendar
    int hour = 0, minute = 0;              ///< local clock
    double second = 0;                     ///< [0, 60)
    int offsetMinutes = 0;                 ///< local clock minus UTC: +120 for +02:00
};

/// Parses `YYYY-MM-DDTHH:MM[:SS[.fff]]` followed by `Z` or an offset `+HH:MM`, `-HH:MM`, `+HHMM` or
/// `+HH` (ISO 8601 extended format; the offset is required, since a time without one names no
/// instant). Years 1583..9999 (the Gregorian calendar), offsets within +-14:00. On failure returns
/// nothing and sets `error` to what is wrong, e.g. "month 13 is not 1..12".
std::optional<CivilTime> parseIsoTime(std::string_view text, std::string& error);

/// The same instant written back as `YYYY-MM-DDTHH:MM:SS+HH:MM` (seconds rounded down).
std::string formatIsoTime(const CivilTime& time);

/// The Julian day (days since -4712 January 1, 12h) of the instant, on the UTC time scale: Meeus,
/// "Astronomical Algorithms" (2nd ed., 1998), formula 7.1.
double julianDayUtc(const CivilTime& time);

/// The hour of the local clock, as written, in [0, 24): 20.5 for `2024-06-21T20:30+02:00`. What the
/// scene's time-of-day effects (lit windows) read.
double localClockHour(const CivilTime& time);

/// The instant `seconds` (any sign) after `start`, on start's clock (its UTC offset): what animation
/// keyframes of the time of day interpolate.
CivilTime civilTimeAfter(const CivilTime& start, double seconds);

/// Days in a month of the Gregorian calendar.
int daysInMonth(int year, int month);

} // namespace urbis
