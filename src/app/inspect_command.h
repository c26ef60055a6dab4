// `urbis inspect`: what an OSM file holds, what was dropped and why, the extent in metres.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace urbis {

struct InspectOptions {
    std::string osmFile;
    std::string bbox;
    bool json = false;
};

void addInspectCommand(CLI::App& app, InspectOptions& options);

/// Imports the file and prints the summary (or the JSON object) on stdout.
void runInspect(const InspectOptions& options);

} // namespace urbis
