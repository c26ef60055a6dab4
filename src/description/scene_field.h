// What every front-end knows of one key of the scene description: its name in the scene file, the
// command-line option that sets it, one line of help and how far a change of it reaches. The list of
// them is visitSceneFields (description/scene_fields.h); the reader, the writer, the command line
// and the viewer's panel are made from it.
#pragma once

namespace urbis {

/// What a change of a key asks of a front-end that shows the scene live (the viewer), least first.
enum class SceneChange {
    None,      ///< nothing that shows: keys that only the written files read
    Display,   ///< the same samples shown otherwise (the exposure, the denoiser)
    Restart,   ///< the same scene, the image starts over (the camera, the integrator)
    Resize,    ///< a new film (its width and height)
    Relight,   ///< the same geometry under other light (the sun, the sky, the time of day)
    Rebuild,   ///< the scene is built again (the city, its geometry, materials, terrain, ...)
};

/// One key of the scene file.
struct Field {
    const char* key;    ///< its name in its JSON object: "max_depth"
    /// The command-line option that sets it: one of its own ("--max-depth"), or one that sets several
    /// keys in one value ("--sun" sets sun.elevation and sun.azimuth; app/scene_options.cpp parses
    /// those). A boolean's option "--no-..." sets it false. nullptr only for keyframe arrays.
    const char* flag;
    const char* help;   ///< one line: the option's help and the panel's tooltip
    SceneChange change = SceneChange::Rebuild;
};

} // namespace urbis
