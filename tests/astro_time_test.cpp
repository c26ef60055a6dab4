// ISO 8601 times (astro/civil_time.h): a table of good strings with the instant and local hour each
// names, a table of bad ones with the error each gives, and Julian days against Meeus.
#include "astro/civil_time.h"

#include <gtest/gtest.h>

namespace urbis {
namespace {

struct GoodTime {
    const char* text;
    double julianDay;   ///< of the instant, UTC
    double localHour;
};

TEST(AstroTime, ParsesGoodStrings) {
    // 2024-06-21T18:30Z is JD 2460483.2708333 (Meeus 7.1 by hand: 2460482.5 + 18.5 / 24).
    const GoodTime table[] = {
        {"2024-06-21T20:30+02:00", 2460483.2708333, 20.5},
        {"2024-06-21T18:30Z", 2460483.2708333, 18.5},
        {"2024-06-21T18:30:00Z", 2460483.2708333, 18.5},
        {"2024-06-21T18:30:00.000Z", 2460483.2708333, 18.5},
        {"2024-06-21T20:30+0200", 2460483.2708333, 20.5},
        {"2024-06-21T20:30+02", 2460483.2708333, 20.5},
        {"2024-06-21T11:00-07:30", 2460483.2708333, 11.0},
        {"2024-06-22T04:30+10:00", 2460483.2708333, 4.5},
        {"2024-02-29T00:00Z", 2460369.5, 0.0},           // a leap day
        {"2000-01-01T12:00Z", 2451545.0, 12.0},          // J2000.0
        {"2000-01-01T13:00+01:00", 2451545.0, 13.0},
        {"2003-10-17T12:30:30-07:00", 2452930.312847, 12.508333}, // NREL SPA's example: JD 2452930.312847
        {"1957-10-04T19:26:24Z", 2436116.31, 19.44},     // Meeus example 7.a: 1957 October 4.81 = JD 2436116.31
        {"1600-12-31T00:00Z", 2305812.5, 0.0},           // Meeus p. 62
        {"2024-12-31T23:59:59.5Z", 2460676.4999942, 23.9998611},
    };
    for (const GoodTime& g : table) {
        std::string error;
        const std::optional<CivilTime> t = parseIsoTime(g.text, error);
        ASSERT_TRUE(t.has_value()) << g.text << ": " << error;
        EXPECT_NEAR(julianDayUtc(*t), g.julianDay, 1e-6) << g.text;
        EXPECT_NEAR(localClockHour(*t), g.localHour, 1e-6) << g.text;
    }
}

TEST(AstroTime, RefusesBadStringsWithTheReason) {
    const std::pair<const char*, const char*> table[] = {
        {"", "expected YYYY-MM-DDTHH:MM"},
        {"2024-06-21", "expected YYYY-MM-DDTHH:MM"},
        {"2024-06-21 20:30Z", "expected YYYY-MM-DDTHH:MM"},
        {"2024-6-21T20:30Z", "expected YYYY-MM-DDTHH:MM"},
        {"20240621T2030Z", "expected YYYY-MM-DDTHH:MM"},
        {"2024-06-21T20:30", "no UTC offset"},
        {"2024-06-21T20:30:00", "no UTC offset"},
        {"2024-06-21T20:30 +02:00", "expected YYYY-MM-DDTHH:MM"},
        {"2024-06-21T20:30+2", "bad UTC offset"},
        {"2024-06-21T20:30+02:0", "bad UTC offset"},
        {"2024-06-21T20:30+02:60", "UTC offset minutes 60"},
        {"2024-06-21T20:30+15:00", "beyond +-14:00"},
        {"2024-06-21T20:30Zulu", "unexpected text"},
        {"2024-06-21T20:30:5Z", "expected YYYY-MM-DDTHH:MM"},
        {"2024-06-21T20:30:00.Z", "expected YYYY-MM-DDTHH:MM"},
        {"2024-13-01T00:00Z", "month 13 is not 1..12"},
        {"2024-00-01T00:00Z", "month 0 is not 1..12"},
        {"2023-02-29T00:00Z", "day 29 is not in 2023-02"},
        {"2024-04-31T00:00Z", "day 31 is not in 2024-04"},
        {"2024-06-21T24:00Z", "hour 24 is not 0..23"},
        {"2024-06-21T20:60Z", "minute 60 is not 0..59"},
        {"2024-06-21T20:30:60Z", "second 60 is not 0..59"},
        {"1582-10-10T00:00Z", "before 1583"},
        {"noon", "expected YYYY-MM-DDTHH:MM"},
    };
    for (const auto& [text, reason] : table) {
        std::string error;
        EXPECT_FALSE(parseIsoTime(text, error).has_value()) << text;
        EXPECT_NE(error.find(reason), std::string::npos) << text << " gave: " << error;
    }
}

TEST(AstroTime, FormatsWhatItParses) {
    for (const char* text : {"2024-06-21T20:30:00+02:00", "1999-12-31T23:59:59-09:30", "2000-01-01T00:00:00+00:00"}) {
        std::string error;
        const std::optional<CivilTime> t = parseIsoTime(text, error);
        ASSERT_TRUE(t.has_value()) << text;
        EXPECT_EQ(formatIsoTime(*t), text);
    }
}

} // namespace
} // namespace urbis
