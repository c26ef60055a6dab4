// What the viewer holds and does, apart from its window: the scene description and the scene built
// from it, the camera and its controller, the render loop, edits, scripts' steps, screenshots and
// scene files. The window (view_window.h) and the headless loop (view_command.cpp) both drive it.
#pragma once

#include "viewer/view_renderer.h"
#include "description/scene_description.h"
#include "film/aov_display.h"
#include "osm/place_names.h"
#include "prepare/prepared_scene.h"
#include "viewer/view_camera.h"
#include "viewer/view_script.h"

#include <nlohmann/json.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace urbis {

/// The render loop's timing since the session began.
struct ViewStats {
    uint64_t frames = 0;            ///< frames that added a sample
    uint64_t rays = 0;
    double secondsRender = 0;       ///< adding the samples (the GPU's kernels or the CPU's render)
    double secondsPicture = 0;      ///< turning the film into the picture (denoise, tone map, a copy to the host where asked)
    std::vector<double> latencies;  ///< seconds from each change to the first picture with a sample after it
    double lastFrameSeconds = 0;    ///< render and picture of the last frame
};

/// Where and within what the session renders: the device ("auto", "cpu" or "cuda"), whether warnings
/// are errors, whether it says which device renders, and the host memory it may take (0: no limit).
struct ViewRunOptions {
    std::string device = "auto";
    bool strict = false;
    bool verbose = false;
    size_t memoryLimit = 0;
};

class ViewSession {
public:
    /// Builds the scene of `scene` and the camera it names (from the framing, placed by geography,
    /// or as given), and starts its image. Throws InputError as `urbis render` would.
    ViewSession(const SceneDescription& scene, const ViewRunOptions& run);
    ~ViewSession();

    const SceneDescription& scene() const { return scene_; }
    /// Makes `next` the scene: rebuilt, restarted or shown anew as far as the change reaches
    /// (sceneChangeOf). On an InputError the scene stays as it was and the message is reported; false.
    bool edit(const SceneDescription& next);
    /// edit() of the scene with `patch` laid over it (patchedScene); `where` names it in messages.
    bool editPatch(const nlohmann::ordered_json& patch, const std::string& where);
    /// Reads the scene file at `path` and makes it the scene; reports and returns false on failure.
    bool load(const std::string& path);
    /// Writes the scene to `path` (atomically); reports and returns false on failure.
    bool save(const std::string& path);
    /// Writes a PNG or EXR: the film as accumulated (with all of width, height and spp 0), or a
    /// fresh render of width x height (0: the film's) at spp (0: the film's samples so far) by
    /// renderOnDevice, as `urbis render` makes it. Reports and returns false on failure.
    bool screenshot(const std::string& path, uint32_t width = 0, uint32_t height = 0, uint32_t spp = 0);

    /// Hands one frame's input to the camera controller; a move restarts the image.
    void cameraInput(const CameraInput& input);
    /// Moves the camera to LON, LAT (degrees), `altitude` metres above the ground, keeping its heading
    /// and pitch (OSM cities only). Reports and returns false where it cannot.
    bool jump(double lon, double lat, float altitude);
    /// Moves the camera to look down on the named OSM feature that best matches `name` (findPlaces),
    /// from kGotoDistance metres at kGotoPitch, keeping its heading. Reports and returns false where
    /// none matches or the city is not from OSM.
    bool goTo(const std::string& name);
    /// The named features of the city inside its bounds (read from its OSM file on first use; none
    /// for the generated city). Reports a file it cannot read, and then has none.
    const std::vector<NamedPlace>& places();
    static constexpr float kGotoDistance = 250.0f;   ///< metres from the feature
    static constexpr float kGotoPitch = -30.0f;      ///< degrees: looking down on it
    /// Undoes the camera's last move.
    void undo();
    CameraController& controller() { return *controller_; }
    const CameraController& controller() const { return *controller_; }

    /// Runs the parts of `step` in order; true when it asks the viewer to end.
    bool runStep(const ScriptStep& step);
    /// Adds a sample of every pixel unless the image holds the scene's spp already; false then.
    bool renderFrame();
    /// Makes the film's picture, as display, exposure and the denoiser ask, and leaves it where it is
    /// made: on the GPU in `deviceRgba` (a mapped OpenGL pixel buffer, ProgressiveRenderer::makePicture)
    /// or its own buffer; on the CPU in the host's. The headless loop and the window's CUDA-OpenGL path.
    void makePicture(uint8_t* deviceRgba = nullptr);
    /// makePicture, the picture then copied to the host.
    Rgb8Image picture();
    /// Whether the image holds the scene's samples per pixel.
    bool complete() const { return renderer_->samples() >= scene_.integrator.spp; }
    uint32_t samples() const { return renderer_->samples(); }

    /// What the viewer shows of the film; a layer other than the image needs a film with AOVs
    /// (setDisplay restarts the image for them).
    FilmDisplay display() const { return display_; }
    void setDisplay(FilmDisplay display);

    const ViewStats& stats() const { return stats_; }
    const ProgressiveRenderer& renderer() const { return *renderer_; }
    size_t sceneBytes() const { return prepared_->scene.memory().total(); }
    /// LON, LAT (degrees) the sky is seen from (skyLocationOf).
    std::array<double, 2> skyLocation() const;
    /// The last problem reported (shown in the window), empty when none; problems go to stderr too.
    const std::string& message() const { return message_; }
    /// Problems reported since the session began.
    size_t problems() const { return problems_; }

private:
    void report(const std::string& problem);
    /// The camera of the scene description for the film's aspect.
    Camera renderCamera() const;
    /// The controller's camera becomes the description's (position and target) and the image restarts.
    void cameraToScene();
    /// The description's camera becomes the controller's.
    void sceneToCamera();
    void restart();
    /// Counts a picture begun at `start` (session clock) in the stats, and the latency of a change it is the first after.
    void pictureMade(double start);
    /// Distance along a unit ray to the first surface of the scene (the controller's CameraProbe).
    float probe(Vec3f origin, Vec3f dir, float maxDistance) const;

    ViewRunOptions run_;
    SceneDescription scene_;
    std::unique_ptr<PreparedScene> prepared_;
    std::unique_ptr<ProgressiveRenderer> renderer_;
    std::unique_ptr<CameraController> controller_;
    FilmDisplay display_ = FilmDisplay::Image;
    ViewStats stats_;
    bool changed_ = false;          ///< a change awaits its first frame (latency)
    double changedAt_ = 0;          ///< seconds on the session's clock
    std::string message_;
    size_t problems_ = 0;
    std::optional<std::vector<NamedPlace>> places_;   ///< read on first use
    std::string placesSource_;                         ///< the OSM file places_ were read from
};

} // namespace urbis

namespace urbis {

/// Runs the steps of `script` from `next` on whose frame has come (frame <= `frame`), advancing
/// `next`; true when one asks the viewer to end.
bool runScriptSteps(ViewSession& session, const std::vector<ScriptStep>& script, size_t& next, uint64_t frame);

} // namespace urbis
