// The command-line options that set parts of the scene description, and --scene / --save-scene:
// a command's scene is its scene file (or its defaults) with the options given on the command line
// applied over it.
#pragma once

#include "description/scene_description.h"

#include <CLI/CLI.hpp>

#include <functional>
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace urbis {

class SceneCommandLine {
public:
    /// `defaults`: the command's scene without a scene file (bench's differs from render's).
    explicit SceneCommandLine(SceneDescription defaults = {});
    SceneCommandLine(const SceneCommandLine&) = delete;             // the options point into it
    SceneCommandLine& operator=(const SceneCommandLine&) = delete;

    /// Registers --scene, --save-scene and the scene's options on `cmd`; with `only`, just the
    /// options named there (bench takes a part of render's).
    void addOptions(CLI::App& cmd, std::initializer_list<std::string_view> only = {});

    /// The scene file's description (readSceneFile), or the defaults without --scene, with every
    /// option given on the command line applied over it. Throws InputError: bad input for the
    /// file, usage for an option's value or a combination that does not hold (firstSceneProblem).
    SceneDescription resolve() const;

    /// --save-scene: where to write the resolved description; empty: nowhere.
    const std::string& saveScenePath() const { return saveScene_; }

private:
    /// Registers `name` bound to `storage`; when given, `apply(description, storage)` sets its part.
    /// Whether `addOptions` registers option `name` (all of them, or those its `only` list names).
    bool wanted(std::string_view name) const;
    template <typename T, typename Apply>
    CLI::Option* bind(CLI::App& cmd, const std::string& name, T& storage, const std::string& help, Apply apply);
    /// Registers --terrain, --dem and --terrain-march (app/terrain_options.cpp).
    void addTerrainOptions(CLI::App& cmd);

    SceneDescription defaults_;
    SceneDescription values_;   ///< storage of the options that take a field's own type
    struct CompoundValues {     ///< storage of the options that take a text ("40,150", "20:100", ...)
        std::string bbox, heightRange, camera, cameraGeo, time, location, sun, geometry;
        std::string planet, cameraOrbit;
    } text_;
    std::string sceneFile_, saveScene_;
    bool noStreets_ = false;   ///< --no-streets
    bool noAerialPerspective_ = false;  ///< --no-aerial-perspective
    std::vector<std::string_view> only_;
    std::vector<std::pair<const CLI::Option*, std::function<void(SceneDescription&)>>> overrides_;
};

} // namespace urbis
