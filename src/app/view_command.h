// `urbis view`: the interactive viewer (docs/viewer.md), with a window or --headless.
#pragma once

#include "app/render_command.h"

#include <CLI/CLI.hpp>

#include <string>

namespace urbis {

/// What `urbis view` does besides the scene: scripts, frames, outputs, the window or none.
struct ViewOptions {
    std::string script;       ///< --script: a viewer script (viewer/view_script.h)
    std::string goTo;         ///< --goto: the name of an OSM feature to look down on first
    uint64_t frames = 0;      ///< --frames: end after this many frames; 0: never (headless: when the image is complete)
    std::string screenshot;   ///< --screenshot: the film as accumulated at the end, PNG or EXR
    std::string windowShot;   ///< --window-shot: the whole window at the end, PNG
    std::string statsFile;    ///< --stats: the render loop's timing, JSON
    bool headless = false;    ///< no window: the render loop and its timing only
};

/// The command line of `urbis view`.
struct ViewCommandLine {
    SceneCommandLine scene;
    RunOptions run;
    ViewOptions view;
};

/// Registers the subcommand's options on `app`.
void addViewCommand(CLI::App& app, ViewCommandLine& commandLine);

/// Runs the viewer. A bad scene, script or option throws InputError before anything opens; once
/// running, problems are reported (stderr, the window) and the viewer goes on; a headless run then
/// ends with an InputError counting them.
void runView(const ViewCommandLine& commandLine);

} // namespace urbis
