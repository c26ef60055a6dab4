// The urbis command: render, inspect, bench, sun, view, export.
#include "app/bench_command.h"
#include "app/export_command.h"
#include "app/inspect_command.h"
#include "app/render_command.h"
#include "app/sun_command.h"
#include "app/view_command.h"
#include "base/input_error.h"
#include "cluster/mpi_world.h"

#include <cstdio>
#include <cstring>
#include <memory>
#include <new>

namespace {

/// The help's footer: the exit codes, one per urbis::FailureKind (docs/cli.md has the same table).
const char* const kExitCodes = "Exit codes:\n"
                               "  0  success\n"
                               "  1  bad input file or data (missing, unreadable, malformed, no buildings in the box)\n"
                               "  2  usage: unknown subcommand or option, bad or missing option value\n"
                               "  3  out of memory (host or GPU), including refusals before any work\n"
                               "  4  GPU or display failure (--device cuda without a usable device, a failed CUDA call, view without a display)\n"
                               "  5  an output file cannot be written\n"
                               "See docs/cli.md for the options, the inspect reasons and these codes.\n";

/// The parser's message, or for a first argument that is no subcommand, one naming it.
std::string usageMessage(const CLI::App& app, const CLI::ParseError& e, int argc, char** argv) {
    if (app.get_subcommands().empty() && argc > 1 && argv[1][0] != '-')
        return std::string("unknown subcommand '") + argv[1] + "' (commands: render, inspect, bench, sun, view, export)";
    return e.what();
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"urbis: ray traces cities from OpenStreetMap, or generated ones.\n\n"
                 "Examples:\n"
                 "  urbis render                                   # the generated default world -> urbis.png\n"
                 "  urbis render --buildings 20000 --spp 64 --out big.png\n"
                 "  urbis render --osm city.osm.pbf --stats stats.json\n"
                 "  urbis render --osm city.osm.pbf --camera-geo -122.397,37.789,300,20,-25\n"
                 "  urbis render --device cuda --spp 256 --out gpu.png\n"
                 "  urbis render --devices all --width 3840 --height 2160 --spp 256 --out big.png   # tiles over every GPU\n"
                 "  urbis render --osm city.osm.pbf --save-scene city.json   # and later: urbis render --scene city.json\n"
                 "  urbis render --scene fly.json --frames 0:119 --out frames/f%04d.png --video fly.mp4   # its animation\n"
                 "  urbis bench --device cuda --buildings 100000 --json bench.json\n"
                 "  urbis inspect city.osm.pbf --json --ids\n"
                 "  urbis render --time 2024-06-21T21:30+02:00 --exposure 8   # the sun, moon and stars of that hour\n"
                 "  urbis sun --location -122.4,37.79 --time 2024-06-21T20:30-07:00 --json\n"
                 "  urbis view --osm city.osm.pbf --width 960 --height 540   # fly through it; save the scene from the panel\n"
                 "  urbis export --osm city.osm.pbf --out city.glb           # the triangle twin for Blender and other tools\n"};
    app.footer(kExitCodes);
    app.set_version_flag("--version", "urbis " URBIS_VERSION);
    app.require_subcommand(1);
    urbis::RenderCommandLine render;
    urbis::InspectOptions inspect;
    urbis::BenchCommandLine bench;
    urbis::SunOptions sun;
    urbis::ViewCommandLine view;
    urbis::ExportCommandLine exportLine;
    urbis::addRenderCommand(app, render);
    urbis::addInspectCommand(app, inspect);
    urbis::addBenchCommand(app, bench);
    urbis::addSunCommand(app, sun);
    urbis::addViewCommand(app, view);
    urbis::addExportCommand(app, exportLine);
    std::unique_ptr<urbis::MpiWorld> world;  // joined only under mpirun
    // A rank that fails ends the whole job: the others would wait for its tiles forever.
    auto fail = [&](int code) {
        if (world && world->ranks() > 1) world->abort(code);
        return code;
    };
    try {
        if (urbis::launchedByMpirun()) world = std::make_unique<urbis::MpiWorld>();
        app.parse(argc, argv);
        if (app.got_subcommand("render")) urbis::runRender(render.resolve(), world.get());
        if (app.got_subcommand("inspect")) urbis::runInspect(inspect);
        if (app.got_subcommand("bench")) urbis::runBench(bench.resolve());
        if (app.got_subcommand("sun")) urbis::runSun(sun);
        if (app.got_subcommand("view")) urbis::runView(view);
        if (app.got_subcommand("export")) urbis::runExport(exportLine);
    } catch (const CLI::Success& e) {
        return app.exit(e);  // --help, --help-all, --version
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "urbis: %s (see urbis --help)\n", usageMessage(app, e, argc, argv).c_str());
        return fail(int(urbis::FailureKind::Usage));
    } catch (const urbis::InputError& e) {
        std::fprintf(stderr, "urbis: %s\n", e.what());
        return fail(int(e.kind()));
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "urbis: out of memory (try fewer buildings, a smaller --bbox or a smaller image)\n");
        return fail(int(urbis::FailureKind::OutOfMemory));
    } catch (const std::exception& e) {
        // A library's own exception no check above foresaw: still one line and an exit code, never an abort.
        std::fprintf(stderr, "urbis: %s (an unexpected failure: please report it with the input)\n", e.what());
        return fail(int(urbis::FailureKind::BadInput));
    }
    return 0;
}
