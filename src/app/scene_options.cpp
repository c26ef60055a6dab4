#include "app/scene_options.h"

#include "app/compound_options.h"
#include "app/option_parsing.h"
#include "base/input_error.h"
#include "description/building_type_names.h"
#include "description/scene_checks.h"
#include "description/scene_fields.h"
#include "description/scene_json.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <type_traits>

namespace urbis {

namespace {

/// `values` as the command line writes them: "3.3,3.1,2.8".
template <typename T>
std::string listText(const T* values, size_t n) {
    std::string text;
    for (size_t i = 0; i < n; ++i) {
        char number[32];
        std::snprintf(number, sizeof number, "%g", double(values[i]));
        if (i) text += ',';
        text += number;
    }
    return text;
}

/// N numbers separated by commas, each in [lo, hi]; throws a usage InputError naming `flag`.
template <typename T, size_t N>
std::array<T, N> numbersIn(const char* flag, const std::string& text, T lo, T hi) {
    const std::vector<double> v = parseNumberList(flag, text, ',', N, N);
    std::array<T, N> out{};
    for (size_t i = 0; i < N; ++i) {
        if (!(v[i] >= double(lo) && v[i] <= double(hi)))
            throw InputError(std::string(flag) + ": each number must be in [" + listText(&lo, 1) + ", " + listText(&hi, 1) +
                                 "], got '" + text + "'",
                             FailureKind::Usage);
        out[i] = T(v[i]);
    }
    return out;
}

Vec3f vec3Of(const std::array<float, 3>& a) { return Vec3f{a[0], a[1], a[2]}; }

template <typename Table>
std::vector<std::string> namesOf(const Table& table) {
    std::vector<std::string> names;
    for (const auto& entry : table) names.emplace_back(choiceName(entry));
    return names;
}

} // namespace

/// Registers an option for each field of visitSceneFields (over the storage `values_`): a number or
/// a text bound to its field, checked against its range or its choices; a boolean as a switch
/// ("--no-..." sets it false); vectors, lists and colour maps as texts parsed when applied; the
/// compound options where their first key is visited.
class SceneCommandLine::Binder {
public:
    Binder(SceneCommandLine& line, CLI::App& cmd) : line_(line), cmd_(cmd) {}

    template <typename F>
    void object(const char* key, F&& fields) {
        if (depth_++ == 0) group_ = std::string("Scene: ") + key;
        fields();
        --depth_;
    }

    template <typename T, typename F>
    void optionalObject(const Field& f, std::optional<T>& value, F&& fields) {
        if (depth_ == 0) group_ = std::string("Scene: ") + f.key;
        compound(f);
        if (!value) value.emplace();   // the storage of its keys' options
        object(f.key, [&] { fields(*value); });
    }

    template <typename T>
    void number(const Field& f, T& value, std::type_identity_t<T> lo, std::type_identity_t<T> hi) {
        CLI::Option* option = start<T>(f, [&] { return add(f, value); });
        if (!option) return;
        if (lo != std::numeric_limits<T>::lowest() || hi != std::numeric_limits<T>::max()) {
            if constexpr (std::is_floating_point_v<T>) option->check(CLI::Range(double(lo), double(hi)));
            else option->check(CLI::Range(lo, hi));
        }
        option->capture_default_str();
        keep<T>(f, option, [&value](T& field) { field = value; });
    }

    void vec3(const Field& f, Vec3f& value, float lo, float hi) {
        std::string& text = line_.texts_.emplace_back();
        CLI::Option* option = start<Vec3f>(f, [&] { return add(f, text); });
        if (!option) return;
        option->type_name(lo < 0.0f ? "X,Y,Z" : "R,G,B")->default_str(listText(&value.x, 3));   // a point, or a colour
        keep<Vec3f>(f, option, [&text, flag = f.flag, lo, hi](Vec3f& field) {
            field = vec3Of(numbersIn<float, 3>(flag, text, lo, hi));
        });
    }

    void optionalVec3(const Field& f, std::optional<Vec3f>&, float lo, float hi) {
        std::string& text = line_.texts_.emplace_back();
        CLI::Option* option = start<std::optional<Vec3f>>(f, [&] { return add(f, text); });
        if (!option) return;
        option->type_name("X,Y,Z|none");
        keep<std::optional<Vec3f>>(f, option, [&text, flag = f.flag, lo, hi](std::optional<Vec3f>& field) {
            if (text == "none") field.reset();
            else field = vec3Of(numbersIn<float, 3>(flag, text, lo, hi));
        });
    }

    template <typename T, size_t N>
    void optionalArray(const Field& f, std::optional<std::array<T, N>>&, T lo, T hi) {
        std::string& text = line_.texts_.emplace_back();
        CLI::Option* option = start<std::optional<std::array<T, N>>>(f, [&] { return add(f, text); });
        if (!option) return;
        option->type_name(std::to_string(N) + " NUMBERS|none");
        keep<std::optional<std::array<T, N>>>(f, option, [&text, flag = f.flag, lo, hi](std::optional<std::array<T, N>>& field) {
            if (text == "none") field.reset();
            else field = numbersIn<T, N>(flag, text, lo, hi);
        });
    }

    void text(const Field& f, std::string& value) {
        CLI::Option* option = start<std::string>(f, [&] { return add(f, value); });
        if (!option) return;
        if (!value.empty()) option->capture_default_str();
        keep<std::string>(f, option, [&value](std::string& field) { field = value; });
    }

    void boolean(const Field& f, bool&) {
        const bool negated = std::string_view(f.flag).starts_with("--no-");
        bool& given = line_.switches_.emplace_back(false);
        CLI::Option* option = start<bool>(f, [&] { return cmd_.add_flag(f.flag, given, f.help)->group(group_); });
        if (!option) return;
        keep<bool>(f, option, [&given, negated](bool& field) { field = negated ? !given : given; });
    }

    template <typename Table>
    void choice(const Field& f, std::string& value, const Table& table) {
        CLI::Option* option = start<std::string>(f, [&] { return add(f, value); });
        if (!option) return;
        option->check(CLI::IsMember(namesOf(table)))->capture_default_str();
        keep<std::string>(f, option, [&value](std::string& field) { field = value; });
    }

    template <typename Table>
    void choiceList(const Field& f, std::vector<std::string>& value, const Table& table) {
        std::string& text = line_.texts_.emplace_back();
        using Names = std::vector<std::string>;
        CLI::Option* option = start<Names>(f, [&] { return add(f, text); });
        if (!option) return;
        const Names names = namesOf(table);
        std::string all;
        for (const std::string& name : names) all += (all.empty() ? "" : ",") + name;
        option->type_name("NAME,...|none");
        std::string shown;
        for (const std::string& name : value) shown += (shown.empty() ? "" : ",") + name;
        option->default_str(shown);
        keep<Names>(f, option, [&text, names, all, flag = std::string(f.flag)](Names& field) {
            Names chosen;
            size_t start = 0;
            while (text != "none" && start <= text.size()) {
                const size_t end = std::min(text.find(',', start), text.size());
                const std::string name = text.substr(start, end - start);
                if (std::find(names.begin(), names.end(), name) == names.end())
                    throw InputError(flag + ": '" + name + "' is not one of " + all + " (or none)", FailureKind::Usage);
                if (std::find(chosen.begin(), chosen.end(), name) == chosen.end()) chosen.push_back(name);
                start = end + 1;
            }
            field = std::move(chosen);
        });
    }

    template <typename E, size_t N>
    void enumeration(const Field& f, E& value, const Choice<E> (&table)[N]) {
        std::string& text = line_.texts_.emplace_back(nameOfChoice(table, value));
        CLI::Option* option = start<E>(f, [&] { return add(f, text); });
        if (!option) return;
        option->check(CLI::IsMember(namesOf(table)))->capture_default_str();
        keep<E>(f, option, [&text, &table](E& field) { field = choiceNamed(table, text).value_or(field); });
    }

    void colourMap(const Field& f, std::map<std::string, Vec3f>&) {
        using Colours = std::map<std::string, Vec3f>;
        std::vector<std::string>& items = line_.lists_.emplace_back();
        CLI::Option* option = start<Colours>(f, [&] { return cmd_.add_option(f.flag, items, f.help)->group(group_); });
        if (!option) return;
        option->type_name("TYPE=R,G,B")->take_all();
        keep<Colours>(f, option, [&items, flag = f.flag](Colours& field) {
            for (const std::string& item : items) {
                const size_t equals = item.find('=');
                const std::string type = item.substr(0, std::min(equals, item.size()));
                if (equals == std::string::npos || !buildingTypeNamed(type))
                    throw InputError(std::string(flag) + ": need TYPE=R,G,B with a building type (" + buildingTypeNameList() +
                                         "), got '" + item + "'",
                                     FailureKind::Usage);
                field[type] = vec3Of(numbersIn<float, 3>(flag, item.substr(equals + 1), 0.0f, 1.0f));
            }
        });
    }

    /// Keyframes are the scene file's alone (docs/animation.md): no option sets them.
    template <typename Keyframes>
    void keyframes(const Field&, Keyframes&) {}

private:
    /// Registers the compound option `f` names, once; true where `f` names one.
    bool compound(const Field& f) {
        const CompoundOption* it = compoundOptionNamed(f.flag);
        if (!it) return false;
        const size_t order = size_t(it - compoundOptions().data());
        if (!line_.wanted(f.flag) || line_.compounds_.count(order)) return true;
        std::string& value = line_.texts_.emplace_back(it->defaultText);
        CLI::Option* option = cmd_.add_option(it->flag, value, it->help)->group(group_);
        if (!it->defaultText.empty()) option->capture_default_str();
        if (it->valueOptional) option->expected(0, 1);
        line_.compounds_[order] = {option, &value};
        return true;
    }

    /// The option of `f`, registered by `add`: nullptr where it is a compound's, not wanted, or
    /// already registered by a key that shares it (of the same type `T`).
    template <typename T, typename Add>
    CLI::Option* start(const Field& f, Add&& add) {
        if (compound(f) || !line_.wanted(f.flag)) return nullptr;
        if (const auto it = line_.keyOptions_.find(f.flag); it != line_.keyOptions_.end()) {
            if (*it->second.type != typeid(T)) throw std::logic_error(std::string(f.flag) + " names keys of two types");
            return nullptr;
        }
        return add();
    }

    template <typename Storage>
    CLI::Option* add(const Field& f, Storage& storage) {
        return cmd_.add_option(f.flag, storage, f.help)->group(group_);
    }

    template <typename T, typename Assign>
    void keep(const Field& f, CLI::Option* option, Assign assign) {
        line_.keyOptions_[f.flag] = {option, &typeid(T), [assign](void* field) { assign(*static_cast<T*>(field)); }};
    }

    SceneCommandLine& line_;
    CLI::App& cmd_;
    std::string group_;
    int depth_ = 0;
};

/// Applies the options given on the command line to the fields of a description, walking
/// visitSceneFields over it.
class SceneCommandLine::Applier {
public:
    explicit Applier(const SceneCommandLine& line) : line_(line) {}

    template <typename F>
    void object(const char*, F&& fields) {
        fields();
    }

    template <typename T, typename F>
    void optionalObject(const Field& f, std::optional<T>& value, F&& fields) {
        if (value) {
            fields(*value);
            return;
        }
        T unset{};   // its keys' options need the object itself first
        const Field* outer = unset_;
        unset_ = &f;
        fields(unset);
        unset_ = outer;
    }

    template <typename T, typename... Range>
    void number(const Field& f, T& value, Range&&...) { apply(f, &value); }
    template <typename T, typename... Range>
    void vec3(const Field& f, T& value, Range&&...) { apply(f, &value); }
    template <typename T, typename... Range>
    void optionalVec3(const Field& f, T& value, Range&&...) { apply(f, &value); }
    template <typename T, typename... Range>
    void optionalArray(const Field& f, T& value, Range&&...) { apply(f, &value); }
    void text(const Field& f, std::string& value) { apply(f, &value); }
    void boolean(const Field& f, bool& value) { apply(f, &value); }
    template <typename T, typename Table>
    void choice(const Field& f, T& value, const Table&) { apply(f, &value); }
    template <typename T, typename Table>
    void choiceList(const Field& f, T& value, const Table&) { apply(f, &value); }
    template <typename T, typename Table>
    void enumeration(const Field& f, T& value, const Table&) { apply(f, &value); }
    template <typename T>
    void colourMap(const Field& f, T& value) { apply(f, &value); }
    template <typename T>
    void keyframes(const Field&, T&) {}

private:
    void apply(const Field& f, void* field) const {
        const auto it = line_.keyOptions_.find(f.flag ? f.flag : "");
        if (it == line_.keyOptions_.end() || it->second.option->count() == 0) return;
        if (unset_)
            throw InputError(std::string(f.flag) + ": sets a key of " + unset_->key + " and needs " + unset_->flag +
                                 " (or the scene file's " + unset_->key + ")",
                             FailureKind::Usage);
        it->second.assign(field);
    }

    const SceneCommandLine& line_;
    const Field* unset_ = nullptr;
};

SceneCommandLine::SceneCommandLine(SceneDescription defaults) : defaults_(std::move(defaults)), values_(defaults_) {}

bool SceneCommandLine::wanted(std::string_view flag) const {
    return only_.empty() || std::find(only_.begin(), only_.end(), flag) != only_.end();
}

void SceneCommandLine::addOptions(CLI::App& cmd, std::initializer_list<std::string_view> only) {
    only_.assign(only.begin(), only.end());
    cmd.add_option("--scene", sceneFile_,
                   "Scene file (.json, docs/scene_files.md) to render; the options given here override its keys");
    cmd.add_option("--save-scene", saveScene_,
                   "Write the scene this command amounts to (every key) to a .json file, then go on");
    Binder binder(*this, cmd);
    visitSceneFields(values_, binder);
    CLI::Option* geo = cmd.get_option_no_throw("--camera-geo");
    if (CLI::Option* camera = cmd.get_option_no_throw("--camera"); geo && camera) geo->excludes(camera);
}

SceneDescription SceneCommandLine::resolve() const {
    SceneDescription d = sceneFile_.empty() ? defaults_ : readSceneFile(sceneFile_, defaults_);
    for (const auto& [order, option] : compounds_)
        if (option.first->count()) compoundOptions()[order].apply(d, *option.second);
    Applier applier(*this);
    visitSceneFields(d, applier);
    // The file alone was checked as it was read: what fails here, the command line's options made.
    if (std::optional<SceneProblem> problem = firstSceneProblem(d))
        throw InputError(problem->option + " (" + problem->key + "): " + problem->message, FailureKind::Usage);
    return d;
}

} // namespace urbis
