// Pearson's chi-square goodness-of-fit test of a sampler against its pdf (pbrt-v4 util/sampling
// tests; Mitsuba test03_chi2): directions binned in (cos theta, phi) about a frame, each bin's
// expected count the pdf integrated over it numerically, bins expected below 5 merged, the
// p-value compared with a significance level after Sidak correction.
#pragma once

#include "math/frame.h"
#include "math/rng.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace urbis::chi2 {

/// Tests per suite that share the family-wise significance of 1 %.
inline double sidakLevel(int tests, double alpha = 0.01) { return 1.0 - std::pow(1.0 - alpha, 1.0 / tests); }

/// Regularised upper incomplete gamma function Q(a, x) (Numerical Recipes 6.2: series below
/// a + 1, continued fraction above): the chi-square p-value is Q(dof / 2, statistic / 2).
inline double upperIncompleteGamma(double a, double x) {
    if (x <= 0) return 1.0;
    const double lnPrefix = -x + a * std::log(x) - std::lgamma(a);
    if (x < a + 1) {
        double term = 1.0 / a, sum = term;
        for (int n = 1; n < 1000 && std::fabs(term) > 1e-15 * std::fabs(sum); ++n) sum += term *= x / (a + n);
        return 1.0 - sum * std::exp(lnPrefix);
    }
    double b = x + 1 - a, c = 1e300, d = 1 / b, h = d;
    for (int i = 1; i < 1000; ++i) {
        const double an = -i * (i - a);
        b += 2;
        d = an * d + b;
        d = std::fabs(d) < 1e-300 ? 1e-300 : d;
        c = b + an / c;
        c = std::fabs(c) < 1e-300 ? 1e-300 : c;
        d = 1 / d;
        const double delta = d * c;
        h *= delta;
        if (std::fabs(delta - 1) < 1e-15) break;
    }
    return std::exp(lnPrefix) * h;
}

struct Outcome {
    double pValue = 0;
    std::string message;  ///< statistic, degrees of freedom, or the reason of a sure failure
};

/// Pearson's test of observed against expected counts (same length, expected summing to the
/// number of samples). Bins expected below 5 are pooled; samples where nothing was expected fail.
inline Outcome pearson(const std::vector<double>& observed, const std::vector<double>& expected) {
    double pooledObserved = 0, pooledExpected = 0;
    std::vector<double> o, e;  // the bins that enter the statistic
    for (size_t i = 0; i < expected.size(); ++i) {
        // A few samples may fall where the numerical integral misses a sliver of the pdf's support.
        if (expected[i] <= 0 && observed[i] >= 10) {
            std::ostringstream s;
            s << observed[i] << " samples in bin " << i << " where the pdf is zero";
            return {0.0, s.str()};
        }
        // Every bin expected below 5 joins one pool (as Mitsuba's chi2 test does) ...
        if (expected[i] < 5) {
            pooledObserved += observed[i];
            pooledExpected += expected[i];
            continue;
        }
        o.push_back(observed[i]);
        e.push_back(expected[i]);
    }
    // ... which stands as a bin of its own if it expects 5 or more, else joins the least expected bin.
    if (pooledExpected >= 5 || e.empty()) {
        o.push_back(pooledObserved);
        e.push_back(pooledExpected);
    } else {
        const size_t least = size_t(std::min_element(e.begin(), e.end()) - e.begin());
        o[least] += pooledObserved;
        e[least] += pooledExpected;
    }
    double statistic = 0;
    for (size_t i = 0; i < e.size(); ++i)
        if (e[i] > 0) statistic += (o[i] - e[i]) * (o[i] - e[i]) / e[i];
    const int bins = int(e.size());
    const int dof = std::max(1, bins - 1);
    std::ostringstream s;
    s << "chi^2 = " << statistic << " with " << dof << " degrees of freedom";
    return {upperIncompleteGamma(0.5 * dof, 0.5 * statistic), s.str()};
}

/// Where directions are binned: cos theta about frame.z in [cosMin, 1], phi about it in [0, 2 pi).
struct DirectionBins {
    Frame frame = Frame::fromZ(Vec3f{0, 0, 1});
    double cosMin = -1;
    int thetaBins = 16, phiBins = 32;
    int subdivisions = 12;  ///< intervals per bin and axis of the numerical integral (integrateBins)
    /// Bins uniform in theta rather than in cos theta: for pdfs over a lat-long map, whose density
    /// times sin theta is bounded (and piecewise constant on bins aligned with the map's cells).
    bool uniformInTheta = false;
    /// Whether the pdf is smooth over each bin (Simpson's rule) or has edges inside bins (the
    /// midpoint rule: Simpson's end points on an edge would count it a third of an interval).
    bool smooth = true;

    /// Polar coordinate of the bins' axis at bin position x in [0, thetaBins]: cos theta.
    double cosAt(double x) const {
        if (!uniformInTheta) return 1.0 - x / thetaBins * (1.0 - cosMin);
        return std::cos(x / thetaBins * std::acos(cosMin));
    }
    /// Bin position in [0, thetaBins] of cos theta.
    double binOf(double z) const {
        if (!uniformInTheta) return (1.0 - z) / (1.0 - cosMin) * thetaBins;
        return std::acos(z) / std::acos(cosMin) * thetaBins;
    }
};

/// A direction sampler: from three uniform numbers, a unit direction, or false for no sample.
using DirectionSampler = std::function<bool(float, float, float, Vec3f&)>;
/// Its solid-angle pdf at a unit direction.
using DirectionPdf = std::function<double(Vec3f)>;

inline Vec3f toLocal(const Frame& f, Vec3f v) { return {dot(v, f.x), dot(v, f.y), dot(v, f.z)}; }

/// The integral of `pdf` over every bin of `bins` (solid angle d omega = d cos theta d phi, or
/// sin theta d theta d phi): composite Simpson's rule on `subdivisions` intervals per axis (error
/// O(h^4) on smooth pdfs), or the midpoint rule where the pdf is piecewise constant on the bins.
inline std::vector<double> integrateBins(const DirectionPdf& pdf, const DirectionBins& bins) {
    std::vector<double> out(size_t(bins.thetaBins) * bins.phiBins, 0.0);
    const double dphi = 2.0 * M_PI / bins.phiBins, thetaMax = std::acos(bins.cosMin);
    const bool simpson = bins.smooth && !bins.uniformInTheta;
    const int n = bins.subdivisions + (simpson && bins.subdivisions % 2 ? 1 : 0);
    const int points = simpson ? n + 1 : n;
    auto position = [&](int i) { return simpson ? double(i) / n : (i + 0.5) / n; };
    auto weight = [&](int i) { return simpson ? (i == 0 || i == n ? 1.0 : (i % 2 ? 4.0 : 2.0)) / (3.0 * n) : 1.0 / n; };
    for (int t = 0; t < bins.thetaBins; ++t)
        for (int p = 0; p < bins.phiBins; ++p) {
            double sum = 0;
            for (int i = 0; i < points; ++i)
                for (int j = 0; j < points; ++j) {
                    double z, jacobian;
                    if (bins.uniformInTheta) {
                        const double theta = (t + position(i)) / bins.thetaBins * thetaMax;
                        z = std::cos(theta);
                        jacobian = std::sin(theta) * thetaMax / bins.thetaBins;
                    } else {
                        z = bins.cosAt(t + position(i));
                        jacobian = (1.0 - bins.cosMin) / bins.thetaBins;
                    }
                    const double phi = (p + position(j)) * dphi;
                    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
                    const Vec3f local{float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)};
                    sum += weight(i) * weight(j) * pdf(bins.frame.toWorld(local)) * jacobian;
                }
            out[size_t(t) * bins.phiBins + p] = sum * dphi;
        }
    return out;
}

/// The total integral of `pdf` over the domain of `bins`.
inline double integratePdf(const DirectionPdf& pdf, const DirectionBins& bins) {
    double total = 0;
    for (double v : integrateBins(pdf, bins)) total += v;
    return total;
}

/// Draws `samples` directions and tests their histogram against `pdf`. A last bin holds samples
/// outside the domain and failed ones; it expects what the pdf leaves outside the domain's integral.
/// Where the pdf has edges inside bins, the integral's error (a few 1e-4) would read as expected
/// failures: there the expected counts are scaled to the sample count, and SamplingPdf and
/// LightsPdf tests check the integral instead.
inline Outcome testDirections(const DirectionSampler& sample, const DirectionPdf& pdf, const DirectionBins& bins,
                              uint32_t samples, uint32_t seed) {
    const size_t cells = size_t(bins.thetaBins) * bins.phiBins;
    std::vector<double> observed(cells + 1, 0.0), expected = integrateBins(pdf, bins);
    double inside = 0;
    for (double& e : expected) inside += e *= samples;
    if (!bins.smooth && inside > 0)
        for (double& e : expected) e *= samples / inside;
    expected.push_back(bins.smooth ? std::max(0.0, double(samples) - inside) : 0.0);
    SampleStream rng{seed, 0, 0};
    for (uint32_t i = 0; i < samples; ++i) {
        rng.sample = i;
        rng.dimension = 0;
        const float u0 = rng.draw(), u1 = rng.draw(), u2 = rng.draw();
        Vec3f dir;
        if (!sample(u0, u1, u2, dir)) {
            observed[cells] += 1;
            continue;
        }
        const Vec3f local = toLocal(bins.frame, dir);
        const double z = std::clamp(double(local.z), -1.0, 1.0);
        if (z < bins.cosMin) {
            observed[cells] += 1;
            continue;
        }
        double phi = std::atan2(double(local.y), double(local.x));
        if (phi < 0) phi += 2.0 * M_PI;
        const int t = std::min(bins.thetaBins - 1, int(bins.binOf(z)));
        const int p = std::min(bins.phiBins - 1, int(phi / (2.0 * M_PI) * bins.phiBins));
        observed[size_t(t) * bins.phiBins + p] += 1;
    }
    return pearson(observed, expected);
}

} // namespace urbis::chi2
