#include "description/animation_json.h"

#include "astro/civil_time.h"
#include "base/input_error.h"
#include "description/animation_fields.h"
#include "description/field_reader.h"
#include "description/field_writer.h"
#include "description/scene_json.h"

#include <algorithm>
#include <cstdio>

namespace urbis {

namespace {

using json = nlohmann::ordered_json;

/// One JSON object of the section, read key by key: every problem an InputError "FILE: PATH.KEY: ...".
class ObjectReader {
public:
    ObjectReader(const json& node, std::string file, std::string path) : node_(node), file_(std::move(file)), path_(std::move(path)) {
        if (!node_.is_object()) throw InputError(file_ + ": " + path_ + ": expected an object");
    }

    [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
        throw InputError(file_ + ": " + path_ + (key.empty() ? "" : "." + key) + ": " + problem);
    }

    /// The value of `key`, or nullptr when the object leaves it out.
    const json* find(const char* key) {
        known_.emplace_back(key);
        const auto it = node_.find(key);
        return it == node_.end() ? nullptr : &*it;
    }

    std::optional<double> number(const char* key, double lo, double hi) {
        const json* node = find(key);
        if (!node) return std::nullopt;
        return numberIn(*node, key, lo, hi);
    }

    double required(const char* key, double lo, double hi, const char* meaning) {
        const std::optional<double> x = number(key, lo, hi);
        if (!x) fail(key, std::string("missing (") + meaning + ")");
        return *x;
    }

    template <size_t N>
    std::optional<std::array<double, N>> numbers(const char* key, const std::array<double, N>& lo, const std::array<double, N>& hi) {
        const json* node = find(key);
        if (!node) return std::nullopt;
        if (!node->is_array() || node->size() != N) fail(key, "expected an array of " + std::to_string(N) + " numbers");
        std::array<double, N> out{};
        for (size_t i = 0; i < N; ++i) {
            const std::string item = std::string(key) + '[' + std::to_string(i) + ']';
            out[i] = numberIn((*node)[i], item, lo[i], hi[i]);
        }
        return out;
    }

    std::optional<Vec3f> point(const char* key) {
        const auto p = numbers<3>(key, {-1e7, -1e7, -1e7}, {1e7, 1e7, 1e7});
        if (!p) return std::nullopt;
        return Vec3f{float((*p)[0]), float((*p)[1]), float((*p)[2])};
    }

    /// Fails on the keys that no read named.
    void finish() const {
        for (const auto& [key, value] : node_.items())
            if (std::find(known_.begin(), known_.end(), key) == known_.end()) fail(key, "unknown key");
    }

private:
    double numberIn(const json& node, const std::string& key, double lo, double hi) const {
        if (!node.is_number()) fail(key, "expected a number");
        const double x = node.get<double>();
        if (!(x >= lo && x <= hi)) {
            char range[64];
            std::snprintf(range, sizeof range, " is out of range %g..%g", lo, hi);
            fail(key, node.dump() + range);
        }
        return x;
    }

    const json& node_;
    std::string file_, path_;
    std::vector<std::string> known_;
};

/// The keyframes of the array `node` (the value of `path` in `file`), each read by `read(object,
/// keyframe)`, their times increasing.
template <typename Keyframe, typename Read>
std::vector<Keyframe> keyframes(const json& node, const std::string& file, const std::string& path, Read read) {
    if (!node.is_array()) throw InputError(file + ": " + path + ": expected an array of keyframes");
    std::vector<Keyframe> out;
    for (size_t i = 0; i < node.size(); ++i) {
        ObjectReader k(node[i], file, path + "[" + std::to_string(i) + "]");
        Keyframe frame;
        frame.time = k.required("time", 0.0, kMaxAnimationSeconds, "seconds from the animation's start");
        read(k, frame);
        k.finish();
        if (!out.empty() && !(frame.time > out.back().time)) {
            char times[96];
            std::snprintf(times, sizeof times, "%g is not after the keyframe before's %g (times must increase)", frame.time, out.back().time);
            k.fail("time", times);
        }
        out.push_back(std::move(frame));
    }
    return out;
}

void readCameraKeyframe(ObjectReader& k, CameraKeyframe& frame) {
    frame.position = k.point("position");
    frame.geo = k.numbers<3>("geo", {-180.0, -90.0, -1e5}, {180.0, 90.0, 1e7});
    if (frame.position && frame.geo) k.fail("geo", "excludes position: give one of them");
    if (!frame.position && !frame.geo) k.fail("", "needs a position ([x, y, z] metres) or a geo ([lon, lat, altitude])");
    frame.target = k.point("target");
    if (const auto heading = k.number("heading", -360.0, 360.0)) frame.heading = float(*heading);
    if (const auto pitch = k.number("pitch", -89.0, 89.0)) frame.pitch = float(*pitch);
    if (frame.heading.has_value() != frame.pitch.has_value())
        k.fail(frame.heading ? "pitch" : "heading", "missing (heading and pitch come together)");
    if (frame.target && frame.heading) k.fail("target", "excludes heading and pitch: give one look");
    if (frame.target && frame.position && !(length(*frame.target - *frame.position) > 0.0f))
        k.fail("target", "is the keyframe's position");
    if (const auto fov = k.number("fov", 1.0, 170.0)) frame.fov = float(*fov);
    if (const json* ease = k.find("ease")) {
        const std::optional<Easing> easing = ease->is_string() ? choiceNamed(kEasings, ease->get<std::string>()) : std::nullopt;
        if (!easing) k.fail("ease", "expected one of linear, ease_in, ease_out, ease_in_out");
        frame.ease = *easing;
    }
}

void readTimeKeyframe(ObjectReader& k, TimeKeyframe& frame) {
    const json* date = k.find("date");
    if (!date) k.fail("date", "missing (an ISO 8601 date and time with its offset, 2024-06-21T20:30+02:00)");
    if (!date->is_string()) k.fail("date", "expected a string");
    frame.date = date->get<std::string>();
    std::string error;
    if (!parseIsoTime(frame.date, error)) k.fail("date", "'" + frame.date + "': " + error);
    if (const auto exposure = k.number("exposure", -20.0, 20.0)) frame.exposure = float(*exposure);
}

json pointJson(Vec3f p) { return {floatJson(p.x), floatJson(p.y), floatJson(p.z)}; }

} // namespace

std::vector<CameraKeyframe> cameraKeyframesFromJson(const json& node, const std::string& file, const std::string& path) {
    return keyframes<CameraKeyframe>(node, file, path, readCameraKeyframe);
}

std::vector<TimeKeyframe> timeKeyframesFromJson(const json& node, const std::string& file, const std::string& path) {
    std::vector<TimeKeyframe> out = keyframes<TimeKeyframe>(node, file, path, readTimeKeyframe);
    for (size_t i = 1; i < out.size(); ++i)
        if (out[i].exposure.has_value() != out[0].exposure.has_value())
            ObjectReader(node[i], file, path + "[" + std::to_string(i) + "]")
                .fail("exposure", "on every time keyframe or on none (" + path + "[0] " +
                                      std::string(out[0].exposure ? "has one)" : "has none)"));
    return out;
}

json keyframesToJson(const std::vector<CameraKeyframe>& keyframes) {
    json out = json::array();
    for (const CameraKeyframe& k : keyframes) {
        json frame = {{"time", k.time}};
        if (k.position) frame["position"] = pointJson(*k.position);
        if (k.geo) frame["geo"] = *k.geo;
        if (k.target) frame["target"] = pointJson(*k.target);
        if (k.heading) frame["heading"] = floatJson(*k.heading);
        if (k.pitch) frame["pitch"] = floatJson(*k.pitch);
        if (k.fov) frame["fov"] = floatJson(*k.fov);
        frame["ease"] = nameOfChoice(kEasings, k.ease);
        out.push_back(frame);
    }
    return out;
}

json keyframesToJson(const std::vector<TimeKeyframe>& keyframes) {
    json out = json::array();
    for (const TimeKeyframe& k : keyframes) {
        json frame = {{"time", k.time}, {"date", k.date}};
        if (k.exposure) frame["exposure"] = floatJson(*k.exposure);
        out.push_back(frame);
    }
    return out;
}

AnimationDescription animationFromJson(const json& node, const std::string& file, const std::string& path) {
    AnimationDescription a;
    FieldReader reader(node, file, path);
    visitAnimationFields(a, reader);
    reader.finish();
    return a;
}

json animationToJson(const AnimationDescription& animation) {
    FieldWriter writer;
    visitAnimationFields(animation, writer);
    return writer.root;
}

} // namespace urbis
