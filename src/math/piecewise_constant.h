// Piecewise-constant distributions over [0, 1) and [0, 1)^2 (pbrt-v4 PiecewiseConstant1D and
// PiecewiseConstant2D, util/sampling.h): built on the host (piecewise_constant.cpp) into one flat
// float array, sampled per ray from a view of it on either backend.
#pragma once

#include "math/vec.h"

#include <cstdint>
#include <vector>

namespace urbis {

/// A 1D distribution of n cells over [0, 1): func[0..n), cdf[0..n] (cdf[0] = 0, cdf[n] = 1) and the
/// integral of func (its mean value). Empty (n = 0) means no table.
struct PiecewiseConstant1DView {
    const float* func = nullptr;
    const float* cdf = nullptr;
    uint32_t n = 0;
    float integral = 0;
};

/// Largest cell index i with cdf[i] <= u (binary search).
URBIS_HD inline uint32_t findCell(const PiecewiseConstant1DView& d, float u) {
    uint32_t lo = 0, hi = d.n;
    while (lo + 1 < hi) {
        uint32_t mid = (lo + hi) / 2;
        if (d.cdf[mid] <= u) lo = mid;
        else hi = mid;
    }
    return lo;
}

/// A point in [0, 1) distributed as func, its density and its cell.
URBIS_HD inline float samplePiecewiseConstant1D(const PiecewiseConstant1DView& d, float u, float& pdf, uint32_t& cell) {
    cell = findCell(d, u);
    float width = d.cdf[cell + 1] - d.cdf[cell];
    float du = width > 0.0f ? (u - d.cdf[cell]) / width : 0.0f;
    pdf = d.integral > 0.0f ? d.func[cell] / d.integral : 0.0f;
    return fminf((float(cell) + du) / float(d.n), 0x1.fffffep-1f);
}

/// A cell index drawn with probability func[i] / sum(func) (the discrete use of the same table), and
/// that probability.
URBIS_HD inline float discretePmf(const PiecewiseConstant1DView& d, uint32_t cell) {
    return d.integral > 0.0f ? d.func[cell] / (d.integral * float(d.n)) : 0.0f;
}
URBIS_HD inline uint32_t sampleDiscrete(const PiecewiseConstant1DView& d, float u, float& pmf) {
    const uint32_t cell = findCell(d, u);
    pmf = discretePmf(d, cell);
    return cell;
}

/// A 2D distribution of nu x nv cells over [0, 1)^2: per row v a conditional 1D table in u, and a
/// marginal 1D table over the rows' integrals. Layout of `data`: nv rows of (func nu, cdf nu + 1,
/// integral 1), then the marginal (func nv, cdf nv + 1, integral 1).
struct PiecewiseConstant2DView {
    const float* data = nullptr;
    uint32_t nu = 0, nv = 0;

    URBIS_HD bool empty() const { return nu == 0; }
    URBIS_HD PiecewiseConstant1DView row(uint32_t v) const {
        const float* r = data + size_t(v) * (2 * nu + 2);
        return {r, r + nu, nu, r[2 * nu + 1]};
    }
    URBIS_HD PiecewiseConstant1DView marginal() const {
        const float* m = data + size_t(nv) * (2 * nu + 2);
        return {m, m + nv, nv, m[2 * nv + 1]};
    }
};

/// A point (u, v) in [0, 1)^2 distributed as func; `pdf` is its density over [0, 1)^2.
URBIS_HD inline Vec2f samplePiecewiseConstant2D(const PiecewiseConstant2DView& d, float u0, float u1, float& pdf) {
    float pdfV, pdfU;
    uint32_t v, u;
    const float y = samplePiecewiseConstant1D(d.marginal(), u1, pdfV, v);
    const float x = samplePiecewiseConstant1D(d.row(v), u0, pdfU, u);
    pdf = pdfV * pdfU;
    return {x, y};
}

/// The density of (u, v) in [0, 1)^2.
URBIS_HD inline float piecewiseConstant2DPdf(const PiecewiseConstant2DView& d, Vec2f p) {
    uint32_t iu = uint32_t(fminf(fmaxf(p.x * float(d.nu), 0.0f), float(d.nu - 1)));
    uint32_t iv = uint32_t(fminf(fmaxf(p.y * float(d.nv), 0.0f), float(d.nv - 1)));
    const float integral = d.marginal().integral;
    return integral > 0.0f ? d.row(iv).func[iu] / integral : 0.0f;
}

/// The flat table of a 1D distribution over `func` (non-negative): func, cdf (n + 1), integral.
std::vector<float> buildPiecewiseConstant1D(const std::vector<float>& func);

/// The flat table (PiecewiseConstant2DView's layout) over `func`, nu x nv values, row v at v * nu.
std::vector<float> buildPiecewiseConstant2D(const std::vector<float>& func, uint32_t nu, uint32_t nv);

/// A 1D view over a table of `size` floats built by buildPiecewiseConstant1D (host or device memory;
/// the integral is read on the host, so it is passed apart).
URBIS_HD inline PiecewiseConstant1DView piecewiseConstant1DView(const float* table, size_t size, float integral) {
    if (size < 2) return {};
    const uint32_t n = uint32_t((size - 2) / 2);
    return {table, table + n, n, integral};
}

} // namespace urbis
