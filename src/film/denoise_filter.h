// The denoiser's per-pixel filter (host+device): the spatial part of SVGF (Schied et al. 2017,
// "Spatiotemporal Variance-Guided Filtering", section 4.3-4.4) on a film with AOVs. Radiance is
// demodulated by albedo (the filter smooths irradiance, so textures stay sharp), each pixel's
// variance comes from the film's second moment of luminance (no temporal history needed), and five
// a-trous wavelet iterations (steps 1, 2, 4, 8, 16) weigh each neighbour by its depth, normal and
// luminance. What the first surface emits (lit windows, lamps) is set apart and added back unfiltered.
// Pixels of different object or part ids never mix, and the sky is left as it is. Both backends
// run the same three passes: prepareDenoise, denoiseStep (iterated), finishDenoise.
#pragma once

#include "film/film_view.h"

namespace urbis {

/// What the filter knows of one pixel besides its signal: from the film's AOVs, fixed over the
/// iterations.
struct DenoiseGuide {
    Vec3f normal;                 ///< unit mean shading normal, world space (zero where none)
    Vec3f albedo;                 ///< the demodulation factor: mean albedo, each channel at least kDenoiseMinAlbedo
    Vec3f emission;               ///< mean emission of the first surface: not filtered, added back
    float depth = 0;              ///< mean z depth, metres (denoise_detail::kNoDepth where no sample hit)
    float depthDx = 0, depthDy = 0;  ///< its change per pixel along x and y, metres
    uint32_t id = kSkyId;         ///< object and part through the pixel's centre; kSkyId: the sky, not filtered
};

/// What the iterations filter: demodulated radiance and the variance of its luminance.
struct DenoiseSignal {
    Vec3f irradiance;             ///< mean radiance less the first surface's emission, over the guide's albedo
    float variance = 0;           ///< of the luminance of `irradiance` as an estimate (of the mean, not of one sample)
};

/// The edge-stopping parameters of SVGF's section 4.4. SVGF used sigma_z 1, sigma_n 128, sigma_l 4
/// (of a one-sample deviation); these, of the deviation of the pixel's mean, were measured best on
/// bench/denoise_mse.py's street views (docs/film.md).
struct DenoiseParams {
    float sigmaDepth = 4.0f;      ///< sigma_z: depth differences in units of the gradient's prediction
    float sigmaNormal = 16.0f;    ///< sigma_n: the exponent of the normals' cosine
    float sigmaLuminance = 2.0f;  ///< sigma_l: luminance differences in standard deviations of the mean
    uint32_t iterations = 5;      ///< a-trous steps 1, 2, 4, ... 2^(iterations-1) pixels
};

/// Bytes per pixel of the denoiser's buffers on either backend: the guide and two signals (one
/// iteration reads one and writes the other).
inline constexpr size_t kDenoiseBytesPerPixel = sizeof(DenoiseGuide) + 2 * sizeof(DenoiseSignal);

/// Bits of a guide's id taken by the surface part (as SurfacePart's kSurfacePartBits).
inline constexpr uint32_t kDenoisePartBits = 5;

/// Albedo channels below this are raised to it before dividing: black surfaces and emitters keep a
/// finite irradiance, and multiplying back undoes the division exactly as far as floats go.
inline constexpr float kDenoiseMinAlbedo = 0.01f;

/// The buffers one a-trous iteration reads and writes, `width` x `height`, row-major.
struct DenoiseBuffers {
    uint32_t width = 0, height = 0;
    const DenoiseGuide* guide = nullptr;
    const DenoiseSignal* in = nullptr;
    DenoiseSignal* out = nullptr;
};

namespace denoise_detail {

/// Depths are positive; this stands for a pixel (or a place off the image) with none.
inline constexpr float kNoDepth = -1.0f;

/// Mean z depth of pixel `pixel`, or kNoDepth where no sample hit a surface.
URBIS_HD inline float meanDepth(const FilmView& film, size_t pixel) {
    const uint32_t n = film.surfaceCount[pixel];
    return n ? film.depthSum[pixel] / float(n) : kNoDepth;
}

/// Depth change per pixel from `centre` towards the neighbours `before` and `after` (one pixel
/// each side, kNoDepth where none): the smaller one-sided difference, so that a depth edge on one
/// side does not bend the plane of the other; zero where neither neighbour has a depth.
URBIS_HD inline float depthSlope(float before, float centre, float after) {
    const float back = centre - before, forward = after - centre;
    const bool backOk = before >= 0, forwardOk = after >= 0;
    if (backOk && forwardOk) return fabsf(back) < fabsf(forward) ? back : forward;
    return backOk ? back : (forwardOk ? forward : 0.0f);
}

/// The B3 spline kernel of the a-trous transform, 1/16 (1 4 6 4 1), by offset -2..2.
URBIS_HD inline float atrousTap(int offset) {
    const int a = offset < 0 ? -offset : offset;
    return a == 0 ? 0.375f : (a == 1 ? 0.25f : 0.0625f);
}

/// The variance at (x, y) through SVGF's 3x3 Gaussian (1 2 1) x (1 2 1) / 16 over pixels of the
/// same id, renormalised: one pixel's few samples estimate their variance poorly (SVGF eq. 5).
URBIS_HD inline float blurredVariance(const DenoiseBuffers& b, uint32_t x, uint32_t y) {
    const uint32_t id = b.guide[size_t(y) * b.width + x].id;
    float sum = 0, weights = 0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int qx = int(x) + dx, qy = int(y) + dy;
            if (qx < 0 || qy < 0 || qx >= int(b.width) || qy >= int(b.height)) continue;
            const size_t q = size_t(qy) * b.width + uint32_t(qx);
            if (b.guide[q].id != id) continue;
            const float w = float((dx == 0 ? 2 : 1) * (dy == 0 ? 2 : 1));
            sum += w * b.in[q].variance;
            weights += w;
        }
    return sum / weights;
}

} // namespace denoise_detail

/// The guide and the starting signal of pixel (x, y) of `film`, which keeps AOVs: albedo, normal
/// and depth are the means of their sums, the depth gradient one-sided differences of the
/// neighbours' depths, and the variance of the mean luminance is the sample variance (second moment
/// less the squared mean, times n / (n - 1)) over n, scaled to irradiance. A pixel of one sample has
/// no variance of its own: it is given the square of its luminance, which lets its neighbours in.
URBIS_HD inline void prepareDenoise(const FilmView& film, uint32_t x, uint32_t y, DenoiseGuide& guide,
                                    DenoiseSignal& signal) {
    using namespace denoise_detail;
    const size_t pixel = film.pixel(x, y);
    const uint32_t n = film.sampleCount[pixel];
    const float inv = n ? 1.0f / float(n) : 0.0f;
    const Vec3f mean = film.radianceSum[pixel] * inv;
    guide = DenoiseGuide{};
    // Parts too: a window's glass and room are of the building's object, and its wall's luminance
    // alone did not keep them apart (bench/denoise_mse.py: 1.5x lower MSE by day with parts, 0.8x without).
    guide.id = film.objectId[pixel] == kSkyId ? kSkyId : (film.objectId[pixel] << kDenoisePartBits) | film.partId[pixel];
    const Vec3f albedo = film.albedoSum[pixel] * inv;
    guide.albedo = Vec3f{fmaxf(albedo.x, kDenoiseMinAlbedo), fmaxf(albedo.y, kDenoiseMinAlbedo),
                         fmaxf(albedo.z, kDenoiseMinAlbedo)};
    guide.emission = film.emissionSum[pixel] * inv;
    const Vec3f normal = film.normalSum[pixel];
    const float length = sqrtf(dot(normal, normal));
    guide.normal = length > 0 ? normal / length : Vec3f{};
    guide.depth = meanDepth(film, pixel);
    // A surface through the centre that no sample hit has no depth to compare: left unfiltered.
    if (guide.depth < 0) guide.id = kSkyId;
    if (guide.depth >= 0) {
        const auto depthAt = [&](int qx, int qy) {
            if (qx < 0 || qy < 0 || qx >= int(film.width) || qy >= int(film.height)) return kNoDepth;
            return meanDepth(film, film.pixel(uint32_t(qx), uint32_t(qy)));
        };
        guide.depthDx = depthSlope(depthAt(int(x) - 1, int(y)), guide.depth, depthAt(int(x) + 1, int(y)));
        guide.depthDy = depthSlope(depthAt(int(x), int(y) - 1), guide.depth, depthAt(int(x), int(y) + 1));
    }
    const Vec3f reflected = mean - guide.emission;
    signal.irradiance = Vec3f{reflected.x / guide.albedo.x, reflected.y / guide.albedo.y, reflected.z / guide.albedo.z};
    const float l = luminance(mean), lr = luminance(reflected);
    const float scale = lr > 0 ? luminance(signal.irradiance) / lr : 1.0f / luminance(guide.albedo);
    const float sampleVariance = n > 1 ? fmaxf(film.luminanceSqSum[pixel] * inv - l * l, 0.0f) * float(n) / float(n - 1)
                                       : l * l;
    signal.variance = sampleVariance * inv * scale * scale;
}

/// One a-trous iteration at pixel (x, y) with taps `step` pixels apart (SVGF eq. 1-4): the weighted
/// mean of the 5x5 taps of the same id, each weighed by the B3 kernel and
///   exp(-|z_p - z_q| / (sigma_z |grad z_p . (p - q)| + eps)) * max(0, n_p . n_q)^sigma_n
///   * exp(-|l_p - l_q| / (sigma_l sqrt(g3x3(var_p)) + eps)),
/// and the variance carried through as sum(w^2 var_q) / (sum w)^2. The sky is copied.
URBIS_HD inline DenoiseSignal denoiseStep(const DenoiseBuffers& b, uint32_t x, uint32_t y, int step,
                                          const DenoiseParams& params) {
    using namespace denoise_detail;
    const size_t p = size_t(y) * b.width + x;
    const DenoiseGuide& gp = b.guide[p];
    const DenoiseSignal& sp = b.in[p];
    if (gp.id == kSkyId) return sp;
    const float lp = luminance(sp.irradiance);
    // Luminance differences far below float precision of lp must not stop the filter.
    const float sigmaL = params.sigmaLuminance * sqrtf(blurredVariance(b, x, y)) + 1e-6f * (lp + 1e-6f);
    Vec3f sum;
    float weights = 0, variance = 0;
    for (int j = -2; j <= 2; ++j)
        for (int i = -2; i <= 2; ++i) {
            const int qx = int(x) + i * step, qy = int(y) + j * step;
            if (qx < 0 || qy < 0 || qx >= int(b.width) || qy >= int(b.height)) continue;
            const size_t q = size_t(qy) * b.width + uint32_t(qx);
            const DenoiseGuide& gq = b.guide[q];
            if (gq.id != gp.id) continue;
            const DenoiseSignal& sq = b.in[q];
            // Depth: relative to the plane the gradient predicts, with a floor of 0.1 % of the depth
            // for the noise of depths averaged over jittered samples.
            const float predicted = fabsf(gp.depthDx * float(i * step) + gp.depthDy * float(j * step));
            const float wz = (i == 0 && j == 0) ? 0.0f
                : fabsf(gp.depth - gq.depth) / (params.sigmaDepth * predicted + 1e-3f * gp.depth + 1e-6f);
            const float wn = powf(fmaxf(dot(gp.normal, gq.normal), 0.0f), params.sigmaNormal);
            const float wl = fabsf(lp - luminance(sq.irradiance)) / sigmaL;
            const float w = atrousTap(i) * atrousTap(j) * wn * expf(-wz - wl);
            sum += sq.irradiance * w;
            weights += w;
            variance += w * w * sq.variance;
        }
    // The centre tap always counts (its normal weight is one unless it has no normal).
    if (weights <= 0) return sp;
    return DenoiseSignal{sum / weights, variance / (weights * weights)};
}

/// Writes the filtered irradiance of pixel (x, y), multiplied back by its albedo, into the film as
/// its radiance sum (mean times sample count), so that the film's mean is the denoised radiance.
/// The sky and pixels without samples stay as they are.
URBIS_HD inline void finishDenoise(const FilmView& film, uint32_t x, uint32_t y, const DenoiseGuide& guide,
                                   const DenoiseSignal& signal) {
    const size_t pixel = film.pixel(x, y);
    const uint32_t n = film.sampleCount[pixel];
    if (guide.id == kSkyId || n == 0) return;
    const Vec3f radiance = Vec3f{signal.irradiance.x * guide.albedo.x, signal.irradiance.y * guide.albedo.y,
                                 signal.irradiance.z * guide.albedo.z} + guide.emission;
    film.radianceSum[pixel] = radiance * float(n);
}

} // namespace urbis
