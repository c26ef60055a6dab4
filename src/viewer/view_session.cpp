#include "viewer/view_session.h"

#include "base/memory_requirement.h"
#include "io/output_paths.h"
#include "base/input_error.h"
#include "cpu/cpu_denoiser.h"
#include "description/celestial_parts.h"
#include "description/scene_json.h"
#include "description/scene_parts.h"
#include "film/film_output.h"
#include "geometry/scene_intersect.h"
#include "osm/geo_projection.h"
#include "viewer/place_search.h"
#include "viewer/scene_edit.h"

#include <chrono>
#include <cstdio>
#include <unistd.h>

namespace urbis {

namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

/// Metres to the orbit pivot when the view meets no surface within a kilometre.
constexpr float kDefaultPivot = 100.0f;

} // namespace

ViewSession::ViewSession(const SceneDescription& scene, const ViewRunOptions& run) : run_(run), scene_(scene) {
    prepared_ = std::make_unique<PreparedScene>(prepareScene(scene_, run_.strict, run_.memoryLimit));
    renderer_ = std::make_unique<ProgressiveRenderer>(prepared_->scene, renderSettingsOf(scene_).integrator, run_.device, run_.verbose);
    controller_ = std::make_unique<CameraController>(
        ViewCamera{}, [this](Vec3f o, Vec3f d, float maxDistance) { return probe(o, d, maxDistance); });
    sceneToCamera();
    cameraToScene();
    changed_ = false;   // the start is no change: latencies count edits only
}

ViewSession::~ViewSession() = default;

void ViewSession::report(const std::string& problem) {
    message_ = problem;
    ++problems_;
    std::fprintf(stderr, "urbis: %s\n", problem.c_str());
}

float ViewSession::probe(Vec3f origin, Vec3f dir, float maxDistance) const {
    Ray ray{origin, dir, 0.0f, maxDistance};
    const SurfaceHit hit = intersectScene(prepared_->scene.view(), ray);
    return hit.valid() ? hit.t : 2.0f * maxDistance + 1.0f;
}

Camera ViewSession::renderCamera() const {
    return cameraOf(scene_.camera, float(scene_.film.width) / float(scene_.film.height), prepared_->origin,
                    prepared_->framingPieces, groundOf(prepared_->scene));
}

void ViewSession::sceneToCamera() {
    const Camera camera = renderCamera();
    float pivot = kDefaultPivot;
    if (scene_.camera.position && scene_.camera.target) pivot = length(*scene_.camera.target - *scene_.camera.position);
    else if (const float hit = probe(camera.position, camera.forward, 1000.0f); hit <= 1000.0f) pivot = hit;
    controller_->jumpTo(viewCameraLookingAt(camera.position, camera.position + camera.forward * pivot));
}

void ViewSession::cameraToScene() {
    const ViewCamera& c = controller_->camera();
    scene_.camera.position = c.position;
    scene_.camera.target = viewTarget(c);
    scene_.camera.geo.reset();
    restart();
}

void ViewSession::restart() {
    const bool aovs = scene_.film.denoise || display_ != FilmDisplay::Image;
    renderer_->restart(renderCamera(), renderSettingsOf(scene_), aovs);
    changed_ = true;
    changedAt_ = now();
}

bool ViewSession::edit(const SceneDescription& next) {
    const SceneChange change = sceneChangeOf(scene_, next);
    if (change == SceneChange::None) {
        scene_ = next;
        return true;
    }
    const double start = now();
    try {
        if (change == SceneChange::Rebuild) {
            auto prepared = std::make_unique<PreparedScene>(prepareScene(next, false, run_.memoryLimit));
            auto renderer = std::make_unique<ProgressiveRenderer>(prepared->scene, renderSettingsOf(next).integrator, run_.device,
                                                                  run_.verbose);
            renderer_ = std::move(renderer);   // the old renderer refers to the old scene: it goes first
            prepared_ = std::move(prepared);
        }
        const SceneDescription before = scene_;
        scene_ = next;
        if (change == SceneChange::Display) {
            if (scene_.film.denoise && !renderer_->hasAovs()) restart();
            return true;
        }
        try {
            if (sceneToJson(before)["camera"] != sceneToJson(next)["camera"]) sceneToCamera();
            cameraToScene();
        } catch (const InputError&) {
            scene_ = before;   // a camera that cannot be placed: the scene as it was
            throw;
        }
    } catch (const InputError& e) {
        report(e.what());
        return false;
    }
    changedAt_ = start;   // the latency counts the rebuild too
    return true;
}

bool ViewSession::editPatch(const nlohmann::ordered_json& patch, const std::string& where) {
    try {
        return edit(patchedScene(scene_, patch, where));
    } catch (const InputError& e) {
        report(e.what());
        return false;
    }
}

bool ViewSession::load(const std::string& path) {
    try {
        return edit(readSceneFile(path));
    } catch (const InputError& e) {
        report(e.what());
        return false;
    }
}

bool ViewSession::save(const std::string& path) {
    try {
        checkOutputPath("save", path, {".json"});
        writeSceneFile(scene_, path);
        std::fprintf(stderr, "urbis: saved the scene to %s\n", path.c_str());
        return true;
    } catch (const InputError& e) {
        report(e.what());
        return false;
    }
}

bool ViewSession::screenshot(const std::string& path, uint32_t width, uint32_t height, uint32_t spp) {
    try {
        checkOutputPath("screenshot", path, {".png", ".exr"});
        const uint32_t layers = filmLayerMaskOf(scene_.film.layers);
        const FilmOutputOptions output{scene_.film.exposure, scene_.film.exrFloat, layers};
        if (!width && !height && !spp) {
            Film film = renderer_->film();
            if (scene_.film.denoise && film.hasAovs()) denoiseCpu(film);
            writeFilm(film, path, output);
        } else {
            SceneDescription shot = scene_;
            if (width) shot.film.width = width;
            if (height) shot.film.height = height;
            shot.integrator.spp = spp ? spp : std::max(renderer_->samples(), 1u);
            const bool aovs = shot.film.denoise || filmOutputNeedsAovs(path, layers);
            requireMemory(hostFilmBytes(shot.film.width, shot.film.height, aovs), run_.memoryLimit, "the screenshot");
            const RenderSettings settings = renderSettingsOf(shot);
            const Camera camera = cameraOf(shot.camera, float(shot.film.width) / float(shot.film.height),
                                           prepared_->origin, prepared_->framingPieces, groundOf(prepared_->scene));
            Film film(settings.width, settings.height, aovs);
            RenderCounters counters;
            DeviceReport device;
            const RendererOptions where{run_.device, {}, Film::bytesFor(film.width, film.height, aovs), run_.verbose, nullptr};
            Renderer::make(prepared_->scene, settings.integrator, where)
                ->render(camera, settings, film.nextSamples(settings.spp), film, shot.film.denoise, isatty(2), counters, device);
            writeFilm(film, path, output);
        }
        std::fprintf(stderr, "urbis: wrote the screenshot %s\n", path.c_str());
        return true;
    } catch (const InputError& e) {
        report(e.what());
        return false;
    }
}

void ViewSession::cameraInput(const CameraInput& input) {
    if (controller_->update(input)) cameraToScene();
}

bool ViewSession::jump(double lon, double lat, float altitude) {
    if (!prepared_->origin.valid) {
        report("jump: the generated city stands at no longitude and latitude (jumps need an OSM city)");
        return false;
    }
    CameraDescription geo = scene_.camera;
    const ViewCamera& c = controller_->camera();
    geo.geo = GeoCameraDescription{lon, lat, altitude, c.heading, c.pitch};
    geo.position.reset();
    geo.target.reset();
    try {
        const Camera camera = cameraOf(geo, float(scene_.film.width) / float(scene_.film.height), prepared_->origin, {});
        controller_->jumpTo(viewCameraLookingAt(camera.position, camera.position + camera.forward * c.pivotDistance));
    } catch (const InputError& e) {
        report(e.what());
        return false;
    }
    cameraToScene();
    return true;
}

const std::vector<NamedPlace>& ViewSession::places() {
    const std::string& source = scene_.source.osm;
    if (places_ && placesSource_ == source) return *places_;
    places_.emplace();
    placesSource_ = source;
    if (source.empty() || !prepared_->origin.valid) return *places_;
    std::vector<NamedPlace> all;
    try {
        all = readPlaceNames(source);
    } catch (const InputError& e) {
        report(e.what());
        return *places_;
    }
    // The city's bounds, 100 m wider: a file's features beyond its crop box show nothing to look at.
    Bounds3f city;
    for (const Bounds3f& piece : prepared_->framingPieces) city.extend(piece);
    const GeoProjection projection(LonLat{prepared_->origin.lon, prepared_->origin.lat});
    for (NamedPlace& place : all) {
        const Vec2d local = projection.project(LonLat{place.lon, place.lat});
        const float x = float(local.x), z = float(-local.y);
        if (x >= city.lo.x - 100.0f && x <= city.hi.x + 100.0f && z >= city.lo.z - 100.0f && z <= city.hi.z + 100.0f)
            places_->push_back(std::move(place));
    }
    return *places_;
}

bool ViewSession::goTo(const std::string& name) {
    if (!prepared_->origin.valid) {
        report("goto: the generated city has no named features (jumps by name need an OSM city)");
        return false;
    }
    const std::vector<NamedPlace>& all = places();
    const std::vector<size_t> found = findPlaces(all, name, 1);
    if (found.empty()) {
        report("goto: no feature of " + scene_.source.osm + " is named like '" + name + "'");
        return false;
    }
    const NamedPlace& place = all[found[0]];
    const Vec2d local = GeoProjection(LonLat{prepared_->origin.lon, prepared_->origin.lat}).project(LonLat{place.lon, place.lat});
    // The point looked at: the ground, or the roof, under the feature's position.
    constexpr float kAbove = 1e4f;
    const Vec3f high{float(local.x), kAbove, float(-local.y)};
    const float drop = probe(high, Vec3f{0, -1, 0}, 2.0f * kAbove);
    const Vec3f target{high.x, drop <= 2.0f * kAbove ? kAbove - drop : 0.0f, high.z};
    controller_->jumpTo(viewCameraOverlooking(target, controller_->camera().heading, kGotoPitch, kGotoDistance));
    std::fprintf(stderr, "urbis: went to %s (%.6f, %.6f)\n", place.name.c_str(), place.lon, place.lat);
    cameraToScene();
    return true;
}

std::array<double, 2> ViewSession::skyLocation() const { return skyLocationOf(scene_.astronomy, prepared_->origin); }

void ViewSession::undo() {
    if (controller_->undo()) cameraToScene();
}

bool ViewSession::runStep(const ScriptStep& step) {
    if (!step.load.empty()) load(step.load);
    if (!step.set.is_null()) editPatch(step.set, "script step of frame " + std::to_string(step.frame));
    if (step.mode) controller_->mode = *step.mode;
    if (step.input) cameraInput(*step.input);
    if (step.undo) undo();
    if (step.jump) jump((*step.jump)[0], (*step.jump)[1], float((*step.jump)[2]));
    if (!step.goTo.empty()) goTo(step.goTo);
    if (!step.screenshot.empty()) screenshot(step.screenshot, step.width, step.height, step.spp);
    if (!step.saveScene.empty()) save(step.saveScene);
    return step.quit;
}

void ViewSession::setDisplay(FilmDisplay display) {
    display_ = display;
    if (display != FilmDisplay::Image && !renderer_->hasAovs()) restart();
}

bool ViewSession::renderFrame() {
    if (complete()) return false;
    RenderCounters counters;
    const double start = now();
    renderer_->addSample(counters);
    const double end = now();
    stats_.frames += 1;
    stats_.rays += counters.rays;
    stats_.secondsRender += end - start;
    stats_.lastFrameSeconds = end - start;
    return true;
}

void ViewSession::makePicture(uint8_t* deviceRgba) {
    const double start = now();
    renderer_->makePicture(display_, scene_.film.exposure, scene_.film.denoise, deviceRgba);
    pictureMade(start);
}

Rgb8Image ViewSession::picture() {
    const double start = now();
    renderer_->makePicture(display_, scene_.film.exposure, scene_.film.denoise);
    Rgb8Image image = renderer_->picture();
    pictureMade(start);
    return image;
}

void ViewSession::pictureMade(double start) {
    const double end = now();
    stats_.secondsPicture += end - start;
    stats_.lastFrameSeconds += end - start;
    if (changed_ && renderer_->samples() > 0) {
        stats_.latencies.push_back(end - changedAt_);
        changed_ = false;
    }
}

} // namespace urbis

namespace urbis {

bool runScriptSteps(ViewSession& session, const std::vector<ScriptStep>& script, size_t& next, uint64_t frame) {
    bool quit = false;
    while (!quit && next < script.size() && script[next].frame <= frame) quit = session.runStep(script[next++]);
    return quit;
}

} // namespace urbis
