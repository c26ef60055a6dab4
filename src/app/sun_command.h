// `urbis sun`: where the sun and the moon stand at a date, time and place, as JSON or a line of text.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace urbis {

struct SunOptions {
    std::string time;       ///< ISO 8601 with an offset or Z (required)
    std::string location;   ///< "LON,LAT"; empty: kDefaultLocation
    bool json = false;
};

/// Registers the subcommand's options on `app`.
void addSunCommand(CLI::App& app, SunOptions& options);

/// Prints on stdout {"elevation", "azimuth", "moon": {"elevation", "azimuth", "illuminated_fraction",
/// "phase_angle", "angular_radius"}, "local_hour", "location", "time"} (degrees; azimuth clockwise
/// from north; apparent, refracted positions), or with `json` false one line of text. Throws
/// InputError (usage) on a bad time or location.
void runSun(const SunOptions& options);

} // namespace urbis
