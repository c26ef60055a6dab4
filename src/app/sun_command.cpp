#include "app/sun_command.h"

#include "app/option_parsing.h"
#include "astro/ephemeris.h"
#include "base/input_error.h"
#include "description/scene_description.h"

#include <nlohmann/json.hpp>

#include <cstdio>

namespace urbis {

void addSunCommand(CLI::App& app, SunOptions& o) {
    CLI::App* cmd = app.add_subcommand("sun", "Where the sun and the moon stand at a date, time and place (degrees; "
                                              "azimuth clockwise from north)");
    cmd->add_option("--time", o.time, "ISO 8601 date and time with a UTC offset or Z, e.g. 2024-06-21T20:30+02:00")
        ->required();
    cmd->add_option("--location", o.location, "LON,LAT in degrees (default: Prague, the generated city's place)");
    cmd->add_flag("--json", o.json, "Print JSON: {\"elevation\", \"azimuth\", \"moon\": {...}, ...}");
}

void runSun(const SunOptions& o) {
    std::string error;
    const std::optional<CivilTime> time = parseIsoTime(o.time, error);
    if (!time) throw InputError("--time: '" + o.time + "': " + error, FailureKind::Usage);
    const std::array<double, 2> place = o.location.empty() ? kDefaultLocation : parseLocation("--location", o.location);
    const Ephemeris sky = ephemerisAt(*time, place[0], place[1]);
    if (o.json) {
        const nlohmann::json out = {
            {"elevation", sky.sun.elevation},
            {"azimuth", sky.sun.azimuth},
            {"moon", {{"elevation", sky.moon.sky.elevation}, {"azimuth", sky.moon.sky.azimuth},
                      {"illuminated_fraction", sky.moon.illuminatedFraction}, {"phase_angle", sky.moon.phaseAngle},
                      {"angular_radius", sky.moon.angularRadius}}},
            {"local_hour", localClockHour(*time)},
            {"location", place},
            {"time", formatIsoTime(*time)},
        };
        std::printf("%s\n", out.dump().c_str());
        return;
    }
    std::printf("sun: elevation %.2f deg, azimuth %.2f deg; moon: elevation %.2f deg, azimuth %.2f deg, %.0f %% lit "
                "(at %s, %.4f,%.4f)\n",
                sky.sun.elevation, sky.sun.azimuth, sky.moon.sky.elevation, sky.moon.sky.azimuth,
                100.0 * sky.moon.illuminatedFraction, formatIsoTime(*time).c_str(), place[0], place[1]);
}

} // namespace urbis
