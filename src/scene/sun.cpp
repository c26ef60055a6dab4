#include "scene/sun.h"

#include "math/constants.h"

namespace urbis {

Vec3f directionFromElevationAzimuth(float elevationDeg, float azimuthDeg) {
    float el = elevationDeg * kPi / 180.0f, az = azimuthDeg * kPi / 180.0f;
    return {std::sin(az) * std::cos(el), std::sin(el), -std::cos(az) * std::cos(el)};
}

Sun makeSun(float elevationDeg, float azimuthDeg, float angularRadiusDeg, Vec3f irradiance) {
    Sun sun;
    sun.direction = directionFromElevationAzimuth(elevationDeg, azimuthDeg);
    sun.cosHalfAngle = std::cos(angularRadiusDeg * kPi / 180.0f);
    float solidAngle = 2.0f * kPi * (1.0f - sun.cosHalfAngle);
    sun.radiance = irradiance / solidAngle;
    return sun;
}

} // namespace urbis
