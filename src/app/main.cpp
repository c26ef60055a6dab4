// The urbis command: render, inspect, bench.
#include "app/bench_command.h"
#include "app/inspect_command.h"
#include "app/render_command.h"
#include "model/input_error.h"

#include <cstdio>
#include <new>

int main(int argc, char** argv) {
    CLI::App app{"urbis: ray traces cities from OpenStreetMap, or generated ones.\n\n"
                 "Examples:\n"
                 "  urbis render                                   # the generated default world -> urbis.png\n"
                 "  urbis render --buildings 20000 --spp 64 --out big.png\n"
                 "  urbis render --osm city.osm.pbf --stats stats.json\n"
                 "  urbis render --osm city.osm.pbf --camera-geo -122.397,37.789,300,20,-25\n"
                 "  urbis render --device cuda --spp 256 --out gpu.png\n"
                 "  urbis bench --device cuda --buildings 100000 --json bench.json\n"
                 "  urbis inspect city.osm.pbf --json\n"};
    app.require_subcommand(1);
    urbis::RenderOptions render;
    urbis::InspectOptions inspect;
    urbis::BenchOptions bench;
    urbis::addRenderCommand(app, render);
    urbis::addInspectCommand(app, inspect);
    urbis::addBenchCommand(app, bench);
    try {
        app.parse(argc, argv);
        if (app.got_subcommand("render")) urbis::runRender(render);
        if (app.got_subcommand("inspect")) urbis::runInspect(inspect);
        if (app.got_subcommand("bench")) urbis::runBench(bench);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "urbis: %s (see urbis --help)\n", e.what());
        return 2;
    } catch (const urbis::InputError& e) {
        std::fprintf(stderr, "urbis: %s\n", e.what());
        return 1;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "urbis: out of memory (try fewer buildings, a smaller --bbox or a smaller image)\n");
        return 1;
    }
    return 0;
}
