#include "app/inspect_command.h"

#include "app/option_parsing.h"
#include "osm/osm_import.h"

#include <nlohmann/json.hpp>

#include <cstdio>

namespace urbis {

void addInspectCommand(CLI::App& app, InspectOptions& o) {
    CLI::App* cmd = app.add_subcommand("inspect", "Show what an OSM file holds, what was dropped or repaired and why");
    cmd->add_option("file", o.osmFile, "OpenStreetMap file: .osm, .osm.pbf, .osm.bz2, .osm.gz")->required();
    cmd->add_option("--bbox", o.bbox, "Crop to MINLON,MINLAT,MAXLON,MAXLAT (default: the file's header box)");
    cmd->add_flag("--json", o.json, "Print one JSON object");
    cmd->add_flag("--ids", o.ids, "List the OSM ids (n123, w123, r456) of the objects under each reason");
    cmd->footer("dropped: objects not kept; repaired: objects kept after a fix (geometry made valid, a tag\n"
                "ignored). Every reason is explained in docs/cli.md.");
}

namespace {

/// One value of the text listing: boxes as MINLON,MINLAT,MAXLON,MAXLAT (as --bbox takes them),
/// lists of ids joined by spaces, the rest as JSON.
std::string textOf(const nlohmann::json& value) {
    if (value.is_object() && value.contains("min_lon")) {
        char box[128];
        std::snprintf(box, sizeof box, "%.7f,%.7f,%.7f,%.7f", value["min_lon"].get<double>(),
                      value["min_lat"].get<double>(), value["max_lon"].get<double>(), value["max_lat"].get<double>());
        return box;
    }
    if (!value.is_array()) return value.dump();
    std::string text;
    for (const nlohmann::json& item : value) text += (text.empty() ? "" : " ") + item.get<std::string>();
    return text;
}

} // namespace

void runInspect(const InspectOptions& o) {
    ImportOptions params;
    params.bbox = parseBbox(o.bbox);
    nlohmann::json summary = inspectJson(importOsm(o.osmFile, params), o.ids);
    if (o.json) {
        std::printf("%s\n", summary.dump(2).c_str());
        return;
    }
    std::printf("%s\n", o.osmFile.c_str());
    for (const auto& [key, value] : summary.items()) {
        if (value.is_object()) {
            std::printf("  %s:\n", key.c_str());
            for (const auto& [k, v] : value.items()) std::printf("    %-28s %s\n", k.c_str(), textOf(v).c_str());
        } else {
            std::printf("  %-30s %s\n", key.c_str(), value.dump().c_str());
        }
    }
}

} // namespace urbis
