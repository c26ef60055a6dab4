// The viewer's window: GLFW for the window and the input, Dear ImGui (its GLFW and OpenGL 3 backends)
// for the panel and the overlay, and the picture as an OpenGL texture drawn behind them: from a pixel
// buffer that CUDA writes where the film is on the GPU, else from the host.
#include "viewer/view_window.h"

#include "base/host_memory.h"
#include "viewer/view_panel.h"
#include "base/input_error.h"
#include "film/image.h"
#include "gpu/gpu_gl_buffer.h"
#include "viewer/place_search.h"
#include "viewer/scene_edit.h"

#define GL_GLEXT_PROTOTYPES 1   // pixel buffers (OpenGL 2.1), exported by libGL itself
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <memory>

namespace urbis {

std::string viewerWindowUnavailable() { return {}; }

namespace {

/// GLFW's library state for the life of a window.
struct GlfwLibrary {
    GlfwLibrary() {
        if (!glfwInit()) throw InputError("view: no window can open (no display? --headless runs without one)", FailureKind::Device);
    }
    ~GlfwLibrary() { glfwTerminate(); }
};

/// The picture as a texture, resized with it.
class PictureTexture {
public:
    PictureTexture() { glGenTextures(1, &id_); }
    ~PictureTexture() { glDeleteTextures(1, &id_); }
    /// The picture from host memory.
    void upload(const Rgb8Image& image) {
        bind(image.width, image.height);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, GLsizei(width_), GLsizei(height_), GL_RGB, GL_UNSIGNED_BYTE, image.rgb.data());
    }
    /// The picture from the pixel buffer bound to GL_PIXEL_UNPACK_BUFFER (RGBA, width x height): a
    /// copy on the GPU.
    void uploadBound(uint32_t width, uint32_t height) {
        bind(width, height);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, GLsizei(width_), GLsizei(height_), GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    }
    ImTextureID id() const { return reinterpret_cast<ImTextureID>(uintptr_t(id_)); }

private:
    void bind(uint32_t width, uint32_t height) {
        glBindTexture(GL_TEXTURE_2D, id_);
        if (width == width_ && height == height_) return;
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        GLint unpack = 0;   // storage only: no pixels from a bound pixel buffer
        glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &unpack);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, GLsizei(width), GLsizei(height), 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, GLuint(unpack));
        width_ = width;
        height_ = height;
    }

    GLuint id_ = 0;
    uint32_t width_ = 0, height_ = 0;
};

/// The CUDA film's picture written by the GPU into an OpenGL pixel buffer (CUDA-OpenGL interop) and
/// from there into the texture: no copy through the host.
class InteropPicture {
public:
    InteropPicture() { glGenBuffers(1, &buffer_); }
    ~InteropPicture() {
        cuda_.reset();   // unregistered before OpenGL deletes it
        glDeleteBuffers(1, &buffer_);
    }
    /// The session's picture into `texture`. Throws InputError where CUDA cannot register the buffer.
    void update(ViewSession& session, PictureTexture& texture) {
        const uint32_t width = session.scene().film.width, height = session.scene().film.height;
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, buffer_);
        if (width != width_ || height != height_) {
            cuda_.reset();   // a registered buffer keeps its storage: unregistered to be resized
            width_ = height_ = 0;
            glBufferData(GL_PIXEL_UNPACK_BUFFER, GLsizeiptr(size_t(width) * height * 4), nullptr, GL_STREAM_DRAW);
            cuda_ = std::make_unique<CudaGlBuffer>(buffer_);
            width_ = width;
            height_ = height;
        }
        session.makePicture(cuda_->map());
        cuda_->unmap();
        texture.uploadBound(width, height);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    }

private:
    GLuint buffer_ = 0;
    std::unique_ptr<CudaGlBuffer> cuda_;
    uint32_t width_ = 0, height_ = 0;
};

/// The session's picture into the texture: through the interop buffer where there is one (dropped,
/// saying why, on its first failure), else copied through the host.
void showPicture(ViewSession& session, PictureTexture& texture, std::unique_ptr<InteropPicture>& interop) {
    if (interop) {
        try {
            interop->update(session, texture);
            return;
        } catch (const InputError& e) {
            std::fprintf(stderr, "urbis: %s; the window copies the picture through the host\n", e.what());
            glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
            interop.reset();
        }
    }
    texture.upload(session.picture());
}

/// The window's framebuffer as an image (rows from the top).
Rgb8Image readWindow(GLFWwindow* window) {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window, &w, &h);
    Rgb8Image image{uint32_t(w), uint32_t(h), std::vector<uint8_t>(size_t(w) * size_t(h) * 3)};
    std::vector<uint8_t> rows(image.rgb.size());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, rows.data());
    const size_t stride = size_t(w) * 3;
    for (int y = 0; y < h; ++y) std::copy_n(rows.data() + size_t(h - 1 - y) * stride, stride, image.rgb.data() + size_t(y) * stride);
    return image;
}

/// The panel's own state between frames: text boxes and the edit being made.
struct PanelState {
    SceneDescription draft;        ///< the scene as the panel shows it, ahead of the session while a drag goes on
    bool editing = false;          ///< draft holds an edit not yet handed to the session
    std::string scenePath = "urbis_view.json", shotPath = "urbis_view.png";
    int shotSize[3] = {0, 0, 0};   ///< width, height, spp; 0: the film's
    double jumpTo[3] = {0, 0, 200};
    std::string placeQuery;        ///< the search box of named features
};

/// The camera's keys and mouse of this frame, unless the panel has them.
CameraInput cameraInputOf(GLFWwindow* window, double seconds) {
    const ImGuiIO& io = ImGui::GetIO();
    CameraInput in;
    in.seconds = float(seconds);
    if (!io.WantCaptureKeyboard) {
        const auto down = [&](int key) { return glfwGetKey(window, key) == GLFW_PRESS; };
        in.forward = down(GLFW_KEY_W);
        in.back = down(GLFW_KEY_S);
        in.left = down(GLFW_KEY_A);
        in.right = down(GLFW_KEY_D);
        in.up = down(GLFW_KEY_E);
        in.down = down(GLFW_KEY_Q);
    }
    if (!io.WantCaptureMouse) {
        in.dragging = io.MouseDown[0];
        in.mouseDx = io.MouseDelta.x;
        in.mouseDy = io.MouseDelta.y;
        in.scroll = io.MouseWheel;
    }
    return in;
}

/// The keys that act once per press: Tab (orbit/fly), C (collisions), U or Ctrl+Z (undo), Ctrl+S
/// (save), F12 (screenshot), Escape (quit). True on Escape.
bool handleKeys(GLFWwindow* window, ViewSession& session, PanelState& panel) {
    if (ImGui::GetIO().WantCaptureKeyboard) return false;
    const bool ctrl = glfwGetKey(window, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS || glfwGetKey(window, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS;
    CameraController& camera = session.controller();
    if (ImGui::IsKeyPressed(GLFW_KEY_TAB)) camera.mode = camera.mode == CameraMode::Orbit ? CameraMode::Fly : CameraMode::Orbit;
    if (ImGui::IsKeyPressed(GLFW_KEY_C, false)) camera.collide = !camera.collide;
    if (ImGui::IsKeyPressed(GLFW_KEY_U) || (ctrl && ImGui::IsKeyPressed(GLFW_KEY_Z))) session.undo();
    if (ctrl && ImGui::IsKeyPressed(GLFW_KEY_S, false)) session.save(panel.scenePath);
    if (ImGui::IsKeyPressed(GLFW_KEY_F12, false)) session.screenshot(panel.shotPath);
    return ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false);
}

/// The "view" part of the panel: camera, display, files.
void drawViewControls(ViewSession& session, PanelState& panel) {
    CameraController& camera = session.controller();
    int mode = int(camera.mode);
    ImGui::RadioButton("orbit", &mode, int(CameraMode::Orbit));
    ImGui::SameLine();
    ImGui::RadioButton("fly (Tab)", &mode, int(CameraMode::Fly));
    camera.mode = CameraMode(mode);
    ImGui::Checkbox("keep out of buildings (C)", &camera.collide);
    ImGui::SliderFloat("speed (wheel)", &camera.speed, 1e-3f, 1e3f, "%.3g x height/s", ImGuiSliderFlags_Logarithmic);
    if (ImGui::Button("undo move (U)")) session.undo();
    ImGui::InputScalarN("lon, lat, alt", ImGuiDataType_Double, panel.jumpTo, 3);
    if (ImGui::Button("jump")) session.jump(panel.jumpTo[0], panel.jumpTo[1], float(panel.jumpTo[2]));
    ImGui::InputText("find a place", &panel.placeQuery);
    if (!panel.placeQuery.empty()) {
        const std::vector<NamedPlace>& places = session.places();
        const std::vector<size_t> found = findPlaces(places, panel.placeQuery, 8);
        if (found.empty()) ImGui::TextDisabled("(no feature of the OSM file is named so)");
        for (size_t i : found)
            if (ImGui::Selectable(places[i].name.c_str())) session.goTo(places[i].name);
    }
    int display = int(session.display());
    if (ImGui::Combo("show", &display, kFilmDisplayNames, int(std::size(kFilmDisplayNames)))) session.setDisplay(FilmDisplay(display));

    ImGui::InputText("scene file", &panel.scenePath);
    if (ImGui::Button("load")) session.load(panel.scenePath);
    ImGui::SameLine();
    if (ImGui::Button("save (Ctrl+S)")) session.save(panel.scenePath);
    ImGui::InputText("screenshot", &panel.shotPath);
    ImGui::InputInt3("w, h, spp", panel.shotSize);
    if (ImGui::Button("screenshot (F12)"))
        session.screenshot(panel.shotPath, uint32_t(std::max(panel.shotSize[0], 0)), uint32_t(std::max(panel.shotSize[1], 0)),
                           uint32_t(std::max(panel.shotSize[2], 0)));
}

/// The panel: the view's controls, the time of day, every key of the scene. Edits that restart the
/// image go to the session at once; those that rebuild the scene when the edit is finished.
void drawPanel(ViewSession& session, PanelState& panel) {
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(380, 0), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.85f);
    if (!ImGui::Begin("urbis")) {
        ImGui::End();
        return;
    }
    if (!panel.editing) panel.draft = session.scene();
    if (ImGui::CollapsingHeader("view", ImGuiTreeNodeFlags_DefaultOpen)) drawViewControls(session, panel);
    PanelEdit edit;
    if (ImGui::CollapsingHeader("time of day", ImGuiTreeNodeFlags_DefaultOpen)) edit = drawTimeOfDay(panel.draft, session.skyLocation());
    if (ImGui::CollapsingHeader("scene file", ImGuiTreeNodeFlags_DefaultOpen)) {
        const PanelEdit keys = drawScenePanel(panel.draft);
        edit.changed |= keys.changed;
        edit.committed |= keys.committed;
    }
    ImGui::End();
    if (edit.changed) panel.editing = true;
    if (!panel.editing) return;
    if (edit.committed || sceneChangeOf(session.scene(), panel.draft) < SceneChange::Rebuild) {
        session.edit(panel.draft);
        panel.editing = !edit.committed && ImGui::IsAnyItemActive();
    }
}

/// Frame rate, rays, samples, memory, and the last problem.
void drawOverlay(const ViewSession& session) {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(ImVec2(viewport->Size.x - 8, 8), ImGuiCond_Always, ImVec2(1, 0));
    ImGui::SetNextWindowBgAlpha(0.6f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoMove;
    ImGui::Begin("overlay", nullptr, flags);
    const ViewStats& s = session.stats();
    // The render loop's rate (a sample and its picture), not the idle window's once the image is complete.
    ImGui::Text("%.1f fps  %.3g rays/s", s.lastFrameSeconds > 0 ? 1.0 / s.lastFrameSeconds : 0.0,
                s.secondsRender > 0 ? double(s.rays) / s.secondsRender : 0.0);
    ImGui::Text("%u / %u spp  %s", session.samples(), session.scene().integrator.spp, session.renderer().deviceName().c_str());
    ImGui::Text("host %.0f MB  scene %.0f MB  device %.0f MB", double(residentHostBytes()) / 1e6,
                double(session.sceneBytes()) / 1e6, double(session.renderer().deviceBytes()) / 1e6);
    ImGui::Text("%s  %s", session.controller().mode == CameraMode::Orbit ? "orbit" : "fly",
                session.controller().collide ? "collisions on" : "collisions off");
    if (!session.message().empty()) {
        ImGui::PushTextWrapPos(480);
        ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "%s", session.message().c_str());
        ImGui::PopTextWrapPos();
    }
    ImGui::End();
}

} // namespace

void runViewerWindow(ViewSession& session, const ViewWindowOptions& options) {
    GlfwLibrary glfw;
    const FilmDescription& film = session.scene().film;
    GLFWwindow* window = glfwCreateWindow(int(film.width), int(film.height), "urbis view", nullptr, nullptr);
    if (!window) throw InputError("view: the window did not open (no OpenGL? --headless runs without one)", FailureKind::Device);
    glfwMakeContextCurrent(window);
    glfwSwapInterval(0);   // the render loop, not the display, sets the pace
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;   // no imgui.ini left in the working folder
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 130");
    {
        PictureTexture texture;
        std::unique_ptr<InteropPicture> interop;
        if (session.renderer().device() == "cuda") interop = std::make_unique<InteropPicture>();
        PanelState panel;
        panel.jumpTo[0] = session.skyLocation()[0];   // a jump starts from the city's own place
        panel.jumpTo[1] = session.skyLocation()[1];
        size_t next = 0;
        auto last = std::chrono::steady_clock::now();
        bool ending = false;
        for (uint64_t frame = 0; !ending && !glfwWindowShouldClose(window); ++frame) {
            glfwPollEvents();
            ending = runScriptSteps(session, options.script, next, frame) || (options.frames && frame + 1 >= options.frames);
            const auto now = std::chrono::steady_clock::now();
            const double seconds = std::chrono::duration<double>(now - last).count();
            last = now;

            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            ImGui::NewFrame();
            session.cameraInput(cameraInputOf(window, seconds));
            ending |= handleKeys(window, session, panel);
            drawPanel(session, panel);
            drawOverlay(session);
            const bool rendered = session.renderFrame();
            if (rendered || frame == 0) showPicture(session, texture, interop);
            ImGui::GetBackgroundDrawList()->AddImage(texture.id(), ImVec2(0, 0), ImGui::GetIO().DisplaySize);
            ImGui::Render();

            const FilmDescription& size = session.scene().film;   // the window fits the film
            int ww = 0, wh = 0, w = 0, h = 0;
            glfwGetWindowSize(window, &ww, &wh);
            if (ww != int(size.width) || wh != int(size.height)) glfwSetWindowSize(window, int(size.width), int(size.height));
            glfwGetFramebufferSize(window, &w, &h);
            glViewport(0, 0, w, h);
            glClearColor(0, 0, 0, 1);
            glClear(GL_COLOR_BUFFER_BIT);
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
            if (ending && !options.windowShot.empty()) writePng(readWindow(window), options.windowShot);
            glfwSwapBuffers(window);
            if (!rendered && !ending) glfwWaitEventsTimeout(0.05);   // the image is complete: wait for input, not the CPU
        }
    }
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window);
}

} // namespace urbis
