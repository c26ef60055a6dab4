// `urbis inspect`: what an OSM file holds, what was dropped or repaired and why, its extent and boxes.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace urbis {

struct InspectOptions {
    std::string osmFile;
    std::string bbox;
    bool json = false;
    bool ids = false;   ///< list the OSM ids under each reason
};

/// Registers the subcommand's options on `app`.
void addInspectCommand(CLI::App& app, InspectOptions& options);

/// Imports the file and prints the summary (or the JSON object) on stdout.
void runInspect(const InspectOptions& options);

} // namespace urbis
