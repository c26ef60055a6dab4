// The scene's command-line options that have a syntax of their own: several keys in one value
// ("--sun 40,150" sets sun.elevation and sun.azimuth), or one key checked as its own message says.
// Their keys name them in visitSceneFields (description/scene_fields.h); SceneCommandLine registers
// each where its first key is visited.
#pragma once

#include "description/scene_description.h"

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace urbis {

struct CompoundOption {
    const char* flag;
    std::string help;
    /// Sets the option's keys of `d` from its value; throws a usage InputError naming the option.
    std::function<void(SceneDescription& d, const std::string& value)> apply;
    std::string defaultText = {};   ///< what --help shows as the default; empty: none
    bool valueOptional = false;     ///< the option may come without a value (--planet)
};

/// Every compound option, in the order they apply: --time before --sun (whose angles override the
/// time's sun), --planet before --camera-orbit (which needs a planet).
const std::vector<CompoundOption>& compoundOptions();

/// The compound option named `flag`, or nullptr where `flag` names none.
const CompoundOption* compoundOptionNamed(std::string_view flag);

} // namespace urbis
