#include "description/scene_json.h"

#include "description/field_reader.h"
#include "description/field_writer.h"
#include "description/scene_checks.h"
#include "description/scene_fields.h"
#include "io/atomic_file.h"
#include "base/input_error.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace urbis {

namespace {

using json = nlohmann::ordered_json;

/// The end of the JSON string that opens at text[i] (its closing quote).
size_t stringEnd(const std::string& text, size_t i) {
    for (++i; i < text.size() && text[i] != '"'; ++i)
        if (text[i] == '\\') ++i;
    return i;
}

/// `text` (JSON as dump(2) writes it) with each array that holds no object or array on one line:
/// [0.1, 0.11, 0.09] rather than a number a line.
std::string withFlatArrays(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '"') {  // a string whole: brackets in it are text
            const size_t end = stringEnd(text, i);
            out.append(text, i, end - i + 1);
            i = end;
            continue;
        }
        size_t end = i + 1;
        if (text[i] == '[')
            for (; end < text.size() && !std::strchr("[]{}", text[end]); ++end)
                if (text[end] == '"') end = stringEnd(text, end);
        if (text[i] != '[' || end >= text.size() || text[end] != ']') {
            out += text[i];
            continue;
        }
        out += '[';
        for (size_t k = i + 1; k < end; ++k) {
            if (text[k] == '"') {
                const size_t close = stringEnd(text, k);
                out.append(text, k, close - k + 1);
                k = close;
            } else if (text[k] == ',') {
                out += ", ";
            } else if (text[k] != ' ' && text[k] != '\n') {
                out += text[k];
            }
        }
        out += ']';
        i = end;
    }
    return out;
}

} // namespace

json floatJson(float value) {
    const std::string text = numberText(value);
    const double shortest = std::strtod(text.c_str(), nullptr);
    return float(shortest) == value ? shortest : double(value);
}

std::string sceneFileText(const SceneDescription& description) {
    return withFlatArrays(sceneToJson(description).dump(2)) + "\n";
}

SceneDescription sceneFromJson(const json& json, const std::string& file, const SceneDescription& defaults) {
    SceneDescription d = defaults;
    FieldReader reader(json, file);
    visitSceneFields(d, reader);
    reader.finish();
    if (std::optional<SceneProblem> problem = firstSceneProblem(d))
        throw InputError(file + ": " + problem->key + ": " + problem->message);
    return d;
}

json sceneToJson(const SceneDescription& description) {
    FieldWriter writer;
    visitSceneFields(description, writer);
    return writer.root;
}

nlohmann::ordered_json readJsonFile(const std::string& path, const std::string& what) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot open the " + what + " (" + std::strerror(errno) + ")");
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": cannot read the " + what + " (a folder)");
    std::stringstream text;
    text << in.rdbuf();
    if (in.bad()) throw InputError(path + ": cannot read the " + what);
    try {
        return json::parse(text.str());
    } catch (const json::parse_error& e) {
        // "[json.exception.parse_error.101] parse error at line 2, column 5: ...": the part from "at line".
        std::string why = e.what();
        const size_t at = why.find(" at line ");
        why = at == std::string::npos ? why : why.substr(at + 1);
        for (char& c : why)
            if (c == '\n' || c == '\r') c = ' ';
        throw InputError(path + ": malformed JSON " + why);
    }
}

SceneDescription readSceneFile(const std::string& path, const SceneDescription& defaults) {
    const json parsed = readJsonFile(path, "scene file");
    SceneDescription d = sceneFromJson(parsed, path, defaults);
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    for (std::string* file : {&d.source.osm, &d.terrain.dem}) {
        const std::filesystem::path p(*file);
        if (!p.empty() && p.is_relative() && !folder.empty()) *file = (folder / p).lexically_normal().string();
    }
    return d;
}

void writeSceneFile(const SceneDescription& description, const std::string& path) {
    SceneDescription d = description;
    for (std::string* file : {&d.source.osm, &d.terrain.dem}) {
        const std::filesystem::path p(*file);
        if (p.empty() || !p.is_relative()) continue;
        std::error_code ec;
        const std::filesystem::path folder = std::filesystem::absolute(std::filesystem::path(path)).parent_path();
        const std::filesystem::path relative = std::filesystem::proximate(std::filesystem::absolute(p), folder, ec);
        if (!ec) *file = relative.string();
    }
    writeTextFileAtomically(path, sceneFileText(d));
}

} // namespace urbis
