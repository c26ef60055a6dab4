// Camera paths and time-of-day keyframes (animation/): the camera at a keyframe's time is that
// keyframe, the centripetal Catmull-Rom path is continuous with a continuous direction through every
// keyframe, easing brings it to rest, the date interpolates across midnight, and bad keyframes give
// one line naming the file and the key.
#include "animation/animation_timeline.h"
#include "astro/civil_time.h"
#include "base/input_error.h"
#include "description/animation_json.h"
#include "description/scene_json.h"
#include "scene/sun.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace urbis;

namespace {

CameraKeyframe at(double time, Vec3f position, Vec3f target, float fov = 50.0f, Easing ease = Easing::Linear) {
    CameraKeyframe k;
    k.time = time;
    k.position = position;
    k.target = target;
    k.fov = fov;
    k.ease = ease;
    return k;
}

float distance(Vec3f a, Vec3f b) { return length(a - b); }

/// A fly-around of five keyframes at uneven times and spacings, looking at the centre.
std::vector<CameraKeyframe> flyAround(Easing ease = Easing::Linear) {
    return {at(0.0, {300, 120, 0}, {0, 10, 0}, 50, ease), at(1.5, {0, 150, 300}, {0, 10, 0}, 40, ease),
            at(2.0, {-250, 90, 40}, {10, 20, 0}, 45, ease), at(4.0, {-20, 200, -310}, {0, 10, 0}, 60, ease),
            at(7.0, {290, 80, -20}, {0, 10, 5}, 50, ease)};
}

TimeKeyframe date(double time, std::string text) {
    TimeKeyframe k;
    k.time = time;
    k.date = std::move(text);
    return k;
}

} // namespace

TEST(CameraPath, AtAKeyframesTimeTheCameraIsTheKeyframe) {
    const std::vector<CameraKeyframe> keys = flyAround();
    const CameraPath path(keys, CameraDescription{}, GeoOrigin{});
    for (const CameraKeyframe& k : keys) {
        const CameraDescription c = path.at(k.time);
        ASSERT_TRUE(c.position && c.target);
        EXPECT_EQ(c.position->x, k.position->x);
        EXPECT_EQ(c.position->y, k.position->y);
        EXPECT_EQ(c.position->z, k.position->z);
        EXPECT_EQ(distance(*c.target, *k.target), 0.0f) << "at " << k.time;
        EXPECT_EQ(c.fov, *k.fov);
    }
    // Before the first keyframe and after the last the camera stays at them.
    EXPECT_EQ(distance(*path.at(-1.0).position, *keys.front().position), 0.0f);
    EXPECT_EQ(distance(*path.at(99.0).position, *keys.back().position), 0.0f);
}

TEST(CameraPath, HeadingAndPitchKeyframesLookWhereTheySay) {
    std::vector<CameraKeyframe> keys(3);
    const float headings[] = {350.0f, 20.0f, 100.0f}, pitches[] = {-30.0f, -10.0f, -45.0f};
    for (int i = 0; i < 3; ++i) {
        keys[i].time = i;
        keys[i].position = Vec3f{float(100 * i), 50, 0};
        keys[i].heading = headings[i];
        keys[i].pitch = pitches[i];
    }
    const CameraPath path(keys, CameraDescription{}, GeoOrigin{});
    for (int i = 0; i < 3; ++i) {
        const CameraDescription c = path.at(i);
        const Vec3f want = directionFromElevationAzimuth(pitches[i], headings[i]);
        EXPECT_LT(distance(normalize(*c.target - *c.position), want), 1e-5f) << i;
    }
    // From 350 to 20 degrees the heading turns the short way, through north, not back through south.
    const Vec3f mid = normalize(*path.at(0.5).target - *path.at(0.5).position);
    EXPECT_LT(mid.z, -0.8f) << "looking north halfway";
}

TEST(CameraPath, CentripetalCatmullRomIsContinuousWithAContinuousDirection) {
    const std::vector<CameraKeyframe> keys = flyAround();
    const CameraPath path(keys, CameraDescription{}, GeoOrigin{});
    const double h = 1e-3;
    for (size_t i = 1; i + 1 < keys.size(); ++i) {
        const double t = keys[i].time;
        const Vec3f before = *path.at(t - h).position, here = *path.at(t).position, after = *path.at(t + h).position;
        // C0: both sides meet at the keyframe (within what the speed covers in h).
        EXPECT_LT(distance(before, here), 1.0f) << i;
        EXPECT_LT(distance(after, here), 1.0f) << i;
        // G1: the direction of motion just before equals the one just after (the speeds may differ:
        // the knots are spaced by distance, the keyframes by time).
        const Vec3f in = normalize(here - before), out = normalize(after - here);
        EXPECT_GT(dot(in, out), 0.999f) << "a kink at keyframe " << i;
    }
    // Sampled finely, no step is larger than the path's speed allows anywhere (no jump inside a segment).
    float largest = 0;
    for (double t = 0; t < 7.0; t += 0.01) largest = std::max(largest, distance(*path.at(t).position, *path.at(t + 0.01).position));
    EXPECT_LT(largest, 15.0f);
}

TEST(CameraPath, CentripetalSplineOfPointsOnALineStaysOnIt) {
    // Uneven spacing is where the uniform spline overshoots and loops; the centripetal one does not.
    const std::vector<CameraKeyframe> keys = {at(0, {0, 50, 0}, {0, 0, -100}), at(1, {1, 50, 0}, {0, 0, -100}),
                                              at(2, {200, 50, 0}, {0, 0, -100}), at(3, {201, 50, 0}, {0, 0, -100})};
    const CameraPath path(keys, CameraDescription{}, GeoOrigin{});
    float previous = -1.0f;
    for (double t = 0; t <= 3.0; t += 0.01) {
        const Vec3f p = *path.at(t).position;
        EXPECT_NEAR(p.y, 50.0f, 1e-3f);
        EXPECT_NEAR(p.z, 0.0f, 1e-3f);
        EXPECT_GE(p.x, previous - 1e-3f) << "runs backwards at t = " << t;
        previous = p.x;
    }
}

TEST(CameraPath, EaseInOutComesToRestAtTheKeyframes) {
    const CameraPath linear(flyAround(Easing::Linear), CameraDescription{}, GeoOrigin{});
    const CameraPath eased(flyAround(Easing::EaseInOut), CameraDescription{}, GeoOrigin{});
    const double t = 1.5, h = 1e-3;
    const float linearStep = distance(*linear.at(t).position, *linear.at(t + h).position);
    const float easedStep = distance(*eased.at(t).position, *eased.at(t + h).position);
    EXPECT_GT(linearStep, 0.05f);
    EXPECT_LT(easedStep, linearStep * 0.05f) << "ease_in_out leaves the keyframe at rest";
    EXPECT_EQ(urbis::eased(0.5f, Easing::EaseInOut), 0.5f);
}

TEST(CameraPath, KeyframesWithoutALookTakeTheScenesTarget) {
    CameraKeyframe k;
    k.time = 0;
    k.position = Vec3f{100, 50, 100};
    CameraDescription scene;
    scene.position = Vec3f{1, 2, 3};
    scene.target = Vec3f{5, 6, 7};
    scene.fov = 33;
    const CameraDescription c = CameraPath(std::vector<CameraKeyframe>{k}, scene, GeoOrigin{}).at(0);
    EXPECT_EQ(distance(*c.target, Vec3f{5, 6, 7}), 0.0f);
    EXPECT_EQ(c.fov, 33.0f);
}

TEST(TimeOfDayPath, DatesInterpolateBetweenKeyframesAcrossMidnight) {
    const std::vector<TimeKeyframe> keys = {date(0, "2024-06-21T18:00+02:00"), date(10, "2024-06-22T02:00+02:00"),
                                            date(12, "2024-06-22T01:00Z")};
    EXPECT_EQ(dateAt(keys, 0), "2024-06-21T18:00+02:00");
    EXPECT_EQ(dateAt(keys, -5), "2024-06-21T18:00+02:00");
    EXPECT_EQ(dateAt(keys, 5), "2024-06-21T22:00:00+02:00");
    EXPECT_EQ(dateAt(keys, 7.5), "2024-06-22T00:00:00+02:00");
    // 02:00+02:00 is 00:00Z: an hour later in two seconds, written on the earlier keyframe's clock.
    EXPECT_EQ(dateAt(keys, 11), "2024-06-22T02:30:00+02:00");
    EXPECT_EQ(dateAt(keys, 20), "2024-06-22T01:00Z");
}

TEST(TimeOfDayPath, ExposureFollowsTheTimeKeyframes) {
    std::vector<TimeKeyframe> keys = {date(0, "2024-06-21T18:00+02:00"), date(4, "2024-06-21T23:00+02:00")};
    keys[0].exposure = 0.0f;
    keys[1].exposure = 10.0f;
    EXPECT_EQ(exposureAt(keys, -1), 0.0f);
    EXPECT_EQ(exposureAt(keys, 1), 2.5f);
    EXPECT_EQ(exposureAt(keys, 9), 10.0f);
    SceneDescription d;
    d.animation.time = keys;
    EXPECT_EQ(AnimationTimeline(d, GeoOrigin{}).frame(24 * 2).film.exposure, 5.0f);
}

TEST(TimeOfDayPath, CivilTimeAfterCrossesMonthsYearsAndLeapDays) {
    std::string error;
    const CivilTime t = *parseIsoTime("2023-12-31T23:30:00+01:00", error);
    EXPECT_EQ(formatIsoTime(civilTimeAfter(t, 1800)), "2024-01-01T00:00:00+01:00");
    EXPECT_EQ(formatIsoTime(civilTimeAfter(t, 60.0 * 86400)), "2024-02-29T23:30:00+01:00");
    EXPECT_EQ(formatIsoTime(civilTimeAfter(t, -86400)), "2023-12-30T23:30:00+01:00");
    EXPECT_NEAR((julianDayUtc(civilTimeAfter(t, 12345.5)) - julianDayUtc(t)) * 86400.0, 12345.5, 1e-3);
}

TEST(AnimationTimeline, FramesRunToTheDurationOrTheLastKeyframe) {
    AnimationDescription a;
    a.camera = flyAround();
    EXPECT_EQ(frameCountOf(a), 7u * 24u + 1u);
    a.fps = 10;
    a.duration = 3;
    EXPECT_EQ(frameCountOf(a), 31u);
    SceneDescription d;
    d.animation = a;
    d.animation.time = {date(0, "2024-06-21T12:00Z"), date(3, "2024-06-21T15:00Z")};
    const AnimationTimeline timeline(d, GeoOrigin{});
    const SceneDescription f = timeline.frame(10);   // 1 s
    EXPECT_EQ(f.astronomy.time, "2024-06-21T13:00:00+00:00");
    EXPECT_EQ(distance(*f.camera.position, *CameraPath(a.camera, d.camera, GeoOrigin{}).at(1.0).position), 0.0f);
    EXPECT_FALSE(f.camera.geo);
}

TEST(AnimationJson, ReadsWhatItWrites) {
    AnimationDescription a;
    a.fps = 30;
    a.camera = flyAround(Easing::EaseOut);
    a.camera[2].target.reset();
    a.camera[2].heading = 12.5f;
    a.camera[2].pitch = -20;
    a.camera[3].fov.reset();
    a.time = {date(0, "2024-06-21T18:00+02:00"), date(4, "2024-06-21T23:00+02:00")};
    const AnimationDescription b = animationFromJson(animationToJson(a), "s.json", "animation");
    EXPECT_EQ(animationToJson(b).dump(), animationToJson(a).dump());
    ASSERT_EQ(b.camera.size(), 5u);
    EXPECT_EQ(*b.camera[2].heading, 12.5f);
    EXPECT_FALSE(b.camera[3].fov);
    EXPECT_EQ(b.camera[0].ease, Easing::EaseOut);
}

TEST(AnimationJson, BadKeyframesGiveOneLineNamingTheFileAndTheKey) {
    const std::pair<const char*, const char*> cases[] = {
        {R"({"camera": [{"time": 2, "position": [0, 50, 0]}, {"time": 1, "position": [9, 50, 0]}]})",
         "s.json: animation.camera[1].time: 1 is not after the keyframe before's 2 (times must increase)"},
        {R"({"camera": [{"time": 1, "position": [0, 50, 0]}, {"time": 1, "position": [9, 50, 0]}]})",
         "s.json: animation.camera[1].time: 1 is not after the keyframe before's 1 (times must increase)"},
        {R"({"camera": [{"position": [0, 50, 0]}]})", "s.json: animation.camera[0].time: missing (seconds from the animation's start)"},
        {R"({"camera": [{"time": 0}]})", "s.json: animation.camera[0]: needs a position ([x, y, z] metres) or a geo ([lon, lat, altitude])"},
        {R"({"camera": [{"time": 0, "position": [0, 50, 0], "heading": 10}]})",
         "s.json: animation.camera[0].pitch: missing (heading and pitch come together)"},
        {R"({"camera": [{"time": 0, "position": [0, 50, 0], "target": [0, 0, 0], "heading": 1, "pitch": 2}]})",
         "s.json: animation.camera[0].target: excludes heading and pitch: give one look"},
        {R"({"camera": [{"time": 0, "position": [0, 50, 0], "geo": [1, 2, 3]}]})", "s.json: animation.camera[0].geo: excludes position"},
        {R"({"camera": [{"time": 0, "postion": [0, 50, 0]}]})", "s.json: animation.camera[0]: needs a position"},
        {R"({"camera": [{"time": 0, "position": [0, 50, 0], "fvo": 3}]})", "s.json: animation.camera[0].fvo: unknown key"},
        {R"({"camera": [{"time": 0, "position": [0, 50, 0], "ease": "fast"}]})", "s.json: animation.camera[0].ease: expected one of linear"},
        {R"({"camera": {"time": 0}})", "s.json: animation.camera: expected an array of keyframes"},
        {R"({"time": [{"time": 0}]})", "s.json: animation.time[0].date: missing"},
        {R"({"time": [{"time": 0, "date": "2024-06-21T25:00Z"}]})", "s.json: animation.time[0].date: '2024-06-21T25:00Z': hour 25"},
        {R"({"fps": 0})", "s.json: animation.fps: 0 is out of range 0.01..1000"},
        {R"({"time": [{"time": 0, "date": "2024-06-21T19:30Z", "exposure": 1}, {"time": 1, "date": "2024-06-21T20:30Z"}]})",
         "s.json: animation.time[1].exposure: on every time keyframe or on none (animation.time[0] has one)"},
    };
    for (const auto& [text, message] : cases) {
        nlohmann::ordered_json scene = {{"animation", nlohmann::ordered_json::parse(text)}};
        try {
            sceneFromJson(scene, "s.json");
            ADD_FAILURE() << "accepted " << text;
        } catch (const InputError& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
            EXPECT_EQ(what.rfind(message, 0), 0u) << text << " -> " << what;
        }
    }
}

TEST(AnimationJson, KeyframesThatTheSceneCannotPlaceAreSceneProblems) {
    const std::pair<const char*, const char*> cases[] = {
        {R"({"animation": {"camera": [{"time": 0, "geo": [14.4, 50.1, 300], "heading": 0, "pitch": -20}]}})",
         "s.json: animation.camera[0].geo: needs a city imported from source.osm (--osm)"},
        {R"({"animation": {"camera": [{"time": 0, "position": [0, 50, 0]}]}})",
         "s.json: animation.camera[0]: needs a target, or heading and pitch (camera.target is unset)"},
    };
    for (const auto& [text, message] : cases) {
        try {
            sceneFromJson(nlohmann::ordered_json::parse(text), "s.json");
            ADD_FAILURE() << "accepted " << text;
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()), message);
        }
    }
}
