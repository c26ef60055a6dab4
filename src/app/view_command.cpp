#include "app/view_command.h"

#include "app/memory_limit.h"
#include "io/output_paths.h"
#include "viewer/view_session.h"
#include "viewer/view_window.h"
#include "base/input_error.h"
#include "io/atomic_file.h"
#include "viewer/scene_edit.h"
#include "viewer/view_script.h"

#include <nlohmann/json.hpp>
#include <tbb/global_control.h>
#include <tbb/info.h>

#include <cstdio>
#include <numeric>

namespace urbis {

void addViewCommand(CLI::App& app, ViewCommandLine& line) {
    CLI::App* cmd = app.add_subcommand("view", "Fly through a city in a window, tune its scene and save it (docs/viewer.md)");
    line.scene.addOptions(*cmd);
    RunOptions& o = line.run;
    ViewOptions& v = line.view;
    cmd->add_option("--threads", o.threads, "CPU threads (0: all cores)")->check(CLI::Range(0, 4096))->capture_default_str();
    cmd->add_option("--device", o.device, "auto (the GPU if usable, else the CPU), cpu or cuda")
        ->check(CLI::IsMember({"auto", "cpu", "cuda"}))->capture_default_str();
    addRunOptions(*cmd, o);
    cmd->add_option("--script", v.script, "Viewer script (.json, docs/viewer.md): timed camera moves, parameter changes, screenshots");
    cmd->add_option("--goto", v.goTo, "Start looking down on the OSM feature of this name (its name tag; the best match)");
    cmd->add_option("--frames", v.frames, "End after this many frames (default: when the window closes; headless: when the image has its --spp)")
        ->check(CLI::Range(uint64_t(1), uint64_t(1) << 40));
    cmd->add_option("--screenshot", v.screenshot, "At the end, write the image as accumulated (.png or .exr)");
    cmd->add_option("--window-shot", v.windowShot, "At the end, write the whole window with its panel (.png)");
    cmd->add_option("--stats", v.statsFile, "Write the render loop's timing as JSON (a .json file)");
    cmd->add_flag("--headless", v.headless, "No window: the render loop and its timing only (machines without a display)");
}

namespace {

/// The script's steps, each `set` checked against the scene it will meet (the sets before it laid
/// over `scene`), so that a bad step stops the run before anything opens.
std::vector<ScriptStep> checkedScript(const std::string& path, SceneDescription scene) {
    std::vector<ScriptStep> steps = readScriptFile(path);
    for (size_t i = 0; i < steps.size(); ++i)
        if (!steps[i].set.is_null())
            scene = patchedScene(scene, steps[i].set, path + ": the step of frame " + std::to_string(steps[i].frame) + ": set");
    return steps;
}

/// The headless loop: script steps, then a sample and its picture, each frame. The picture is made
/// (on the GPU where the film is) but not copied to the host: nothing shows it.
void runHeadless(ViewSession& session, const std::vector<ScriptStep>& script, uint64_t frames) {
    size_t next = 0;
    for (uint64_t frame = 0; !frames || frame < frames; ++frame) {
        if (runScriptSteps(session, script, next, frame)) return;
        if (session.renderFrame()) session.makePicture();
        else if (!frames && next == script.size()) return;   // complete, and nothing left to do
    }
}

nlohmann::ordered_json statsJson(const ViewSession& session) {
    const ViewStats& s = session.stats();
    const double frames = double(std::max<uint64_t>(s.frames, 1));
    const double perFrame = (s.secondsRender + s.secondsPicture) / frames;
    const double latency = s.latencies.empty() ? 0.0
                                               : std::accumulate(s.latencies.begin(), s.latencies.end(), 0.0) / double(s.latencies.size());
    return {{"device", session.renderer().device()},
            {"device_name", session.renderer().deviceName()},
            {"width", session.scene().film.width},
            {"height", session.scene().film.height},
            {"frames", s.frames},
            {"samples", session.samples()},
            {"seconds_render", s.secondsRender},
            {"seconds_picture", s.secondsPicture},
            {"ms_per_frame_render", 1e3 * s.secondsRender / frames},
            {"ms_per_frame", 1e3 * perFrame},
            {"fps", perFrame > 0 ? 1.0 / perFrame : 0.0},
            {"fps_render", s.secondsRender > 0 ? frames / s.secondsRender : 0.0},
            {"rays_per_second", s.secondsRender > 0 ? double(s.rays) / s.secondsRender : 0.0},
            {"latencies", s.latencies},
            {"latency_mean", latency},
            {"problems", session.problems()}};
}

} // namespace

void runView(const ViewCommandLine& line) {
    const ViewOptions& v = line.view;
    const RunOptions& run = line.run;
    SceneDescription scene = line.scene.resolve();
    checkOutputPath("--screenshot", v.screenshot, {".png", ".exr"});
    checkOutputPath("--window-shot", v.windowShot, {".png"});
    checkOutputPath("--stats", v.statsFile, {".json"});
    checkOutputPath("--save-scene", line.scene.saveScenePath(), {".json"});
    if (v.headless && !v.windowShot.empty()) throw InputError("--window-shot: --headless has no window", FailureKind::Usage);
    std::vector<ScriptStep> script = v.script.empty() ? std::vector<ScriptStep>{} : checkedScript(v.script, scene);
    if (!v.goTo.empty()) {   // a step before the script's own of frame 0
        ScriptStep goTo;
        goTo.goTo = v.goTo;
        script.insert(script.begin(), goTo);
    }
    if (!v.headless)
        if (const std::string why = viewerWindowUnavailable(); !why.empty()) throw InputError(why, FailureKind::Usage);

    const size_t threads = run.threads ? run.threads : size_t(tbb::info::default_concurrency());
    tbb::global_control threadLimit(tbb::global_control::max_allowed_parallelism, threads);
    ViewSession session(scene, {run.device, run.strict, run.verbose, memoryLimit(run.maxMemory)});
    if (v.headless) runHeadless(session, script, v.frames);
    else runViewerWindow(session, ViewWindowOptions{script, v.frames, v.windowShot});

    if (!v.screenshot.empty()) session.screenshot(v.screenshot);
    if (!line.scene.saveScenePath().empty()) session.save(line.scene.saveScenePath());
    const nlohmann::ordered_json stats = statsJson(session);
    if (!v.statsFile.empty()) writeTextFileAtomically(v.statsFile, stats.dump(2) + "\n");
    std::printf("urbis: viewed %llu frames of %ux%u on %s: %.2f ms a frame (%.1f fps; render %.2f ms), %.3g rays/s",
                (unsigned long long)session.stats().frames, session.scene().film.width, session.scene().film.height,
                session.renderer().device().c_str(), stats["ms_per_frame"].get<double>(), stats["fps"].get<double>(),
                stats["ms_per_frame_render"].get<double>(), stats["rays_per_second"].get<double>());
    if (!session.stats().latencies.empty())
        std::printf("; a change to its first picture: %.1f ms (mean of %zu)", 1e3 * stats["latency_mean"].get<double>(),
                    session.stats().latencies.size());
    std::printf("\n");
    // A script run without a window is a batch job: what went wrong on the way fails it.
    if (v.headless && session.problems())
        throw InputError("view: " + std::to_string(session.problems()) + " problem(s) on the way (said above)");
}

} // namespace urbis
