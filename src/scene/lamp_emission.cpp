#include "scene/lamp_emission.h"

#include <algorithm>
#include <cmath>

namespace urbis {

namespace {

/// A lobe of the fit: a Gaussian with different widths below and above its peak.
double lobe(double lambda, double peak, double below, double above) {
    const double x = (lambda - peak) / (lambda < peak ? below : above);
    return std::exp(-0.5 * x * x);
}

} // namespace

Vec3f blackbodyRgb(float kelvin) {
    const double t = std::clamp(double(kelvin), 1000.0, 40000.0);
    constexpr double kSecondRadiation = 1.4387769e7;   // hc / k, nm K
    double X = 0, Y = 0, Z = 0;
    for (double lambda = 380.0; lambda <= 780.0; lambda += 5.0) {
        const double planck = 1.0 / (std::pow(lambda, 5.0) * std::expm1(kSecondRadiation / (lambda * t)));
        X += planck * (1.056 * lobe(lambda, 599.8, 37.9, 31.0) + 0.362 * lobe(lambda, 442.0, 16.0, 26.7) -
                       0.065 * lobe(lambda, 501.1, 20.4, 26.2));
        Y += planck * (0.821 * lobe(lambda, 568.8, 46.9, 40.5) + 0.286 * lobe(lambda, 530.9, 16.3, 31.1));
        Z += planck * (1.217 * lobe(lambda, 437.0, 11.8, 36.0) + 0.681 * lobe(lambda, 459.0, 26.0, 13.8));
    }
    const double r = std::max(0.0, 3.2404542 * X - 1.5371385 * Y - 0.4985314 * Z);
    const double g = std::max(0.0, -0.9692660 * X + 1.8760108 * Y + 0.0415560 * Z);
    const double b = std::max(0.0, 0.0556434 * X - 0.2040259 * Y + 1.0572252 * Z);
    const double luma = 0.2126 * r + 0.7152 * g + 0.0722 * b;
    return {float(r / luma), float(g / luma), float(b / luma)};
}

} // namespace urbis
