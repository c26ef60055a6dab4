#include "app/inspect_command.h"

#include "app/option_parsing.h"
#include "osm/osm_import.h"

#include <nlohmann/json.hpp>

#include <cstdio>

namespace urbis {

void addInspectCommand(CLI::App& app, InspectOptions& o) {
    CLI::App* cmd = app.add_subcommand("inspect", "Show what an OSM file holds, what was dropped and why");
    cmd->add_option("file", o.osmFile, "OpenStreetMap file: .osm, .osm.pbf, .osm.bz2, .osm.gz")->required();
    cmd->add_option("--bbox", o.bbox, "Crop to MINLON,MINLAT,MAXLON,MAXLAT (default: the file's header box)");
    cmd->add_flag("--json", o.json, "Print one JSON object");
}

void runInspect(const InspectOptions& o) {
    ImportOptions params;
    params.bbox = parseBbox(o.bbox);
    nlohmann::json summary = inspectJson(importOsm(o.osmFile, params));
    if (o.json) {
        std::printf("%s\n", summary.dump(2).c_str());
        return;
    }
    std::printf("%s\n", o.osmFile.c_str());
    for (const auto& [key, value] : summary.items()) {
        if (value.is_object()) {
            std::printf("  %s:\n", key.c_str());
            for (const auto& [k, v] : value.items()) std::printf("    %-28s %s\n", k.c_str(), v.dump().c_str());
        } else {
            std::printf("  %-30s %s\n", key.c_str(), value.dump().c_str());
        }
    }
}

} // namespace urbis
