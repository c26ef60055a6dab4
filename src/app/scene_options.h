// The command-line options that set parts of the scene description, and --scene / --save-scene:
// a command's scene is its scene file (or its defaults) with the options given on the command line
// applied over it. The options are made from the scene's fields (description/scene_fields.h): each
// key's Field names its option and help, its range is the option's check.
#pragma once

#include "description/scene_description.h"

#include <CLI/CLI.hpp>

#include <deque>
#include <functional>
#include <initializer_list>
#include <map>
#include <string>
#include <string_view>
#include <typeinfo>
#include <utility>
#include <vector>

namespace urbis {

class SceneCommandLine {
public:
    /// `defaults`: the command's scene where neither a scene file nor an option sets a key (bench's
    /// differ from render's).
    explicit SceneCommandLine(SceneDescription defaults = {});
    SceneCommandLine(const SceneCommandLine&) = delete;             // the options point into it
    SceneCommandLine& operator=(const SceneCommandLine&) = delete;

    /// Registers --scene, --save-scene and an option for every key of the scene (grouped by the
    /// scene file's sections); with `only`, just the options named there (bench takes a part of
    /// render's).
    void addOptions(CLI::App& cmd, std::initializer_list<std::string_view> only = {});

    /// The scene file's description (readSceneFile over the defaults), or the defaults without
    /// --scene, with every option given on the command line applied over it. Throws InputError: bad
    /// input for the file, usage for an option's value or a combination that does not hold
    /// (firstSceneProblem).
    SceneDescription resolve() const;

    /// --save-scene: where to write the resolved description; empty: nowhere.
    const std::string& saveScenePath() const { return saveScene_; }

private:
    class Binder;    // registers the options, walking visitSceneFields
    class Applier;   // applies the given ones to a description, walking it likewise

    /// An option that sets a key of its own: where its value is kept and how it sets a field of the
    /// key's type (`type`; the keys that share an option share its type).
    struct KeyOption {
        const CLI::Option* option;
        const std::type_info* type;
        std::function<void(void* field)> assign;
    };

    bool wanted(std::string_view flag) const;

    SceneDescription defaults_;
    SceneDescription values_;   ///< storage of the options that take a field's own type
    std::deque<std::string> texts_;                ///< storage of the options that take a text
    std::deque<std::vector<std::string>> lists_;   ///< of the options that may be given again
    std::deque<bool> switches_;                    ///< of the boolean options
    std::string sceneFile_, saveScene_;
    std::vector<std::string_view> only_;
    std::map<std::string, KeyOption, std::less<>> keyOptions_;
    /// The compound options registered (app/compound_options.h) by their order of application,
    /// with their values' storage.
    std::map<size_t, std::pair<const CLI::Option*, const std::string*>> compounds_;
};

} // namespace urbis
