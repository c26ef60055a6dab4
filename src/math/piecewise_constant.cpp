#include "math/piecewise_constant.h"

namespace urbis {

namespace {

/// Appends func, its cdf and its integral for one 1D distribution. A function that is zero
/// everywhere gets a uniform cdf (and integral 0, so that its pdf reads 0).
void appendDistribution(std::vector<float>& out, const float* func, uint32_t n) {
    double sum = 0;
    for (uint32_t i = 0; i < n; ++i) sum += double(func[i]);
    out.insert(out.end(), func, func + n);
    double running = 0;
    out.push_back(0.0f);
    for (uint32_t i = 0; i < n; ++i) {
        running += sum > 0 ? double(func[i]) / sum : 1.0 / double(n);
        out.push_back(i + 1 == n ? 1.0f : float(running));
    }
    out.push_back(float(sum / double(n)));
}

} // namespace

std::vector<float> buildPiecewiseConstant1D(const std::vector<float>& func) {
    std::vector<float> out;
    if (func.empty()) return out;
    out.reserve(2 * func.size() + 2);
    appendDistribution(out, func.data(), uint32_t(func.size()));
    return out;
}

std::vector<float> buildPiecewiseConstant2D(const std::vector<float>& func, uint32_t nu, uint32_t nv) {
    std::vector<float> out;
    if (nu == 0 || nv == 0 || func.size() != size_t(nu) * nv) return out;
    out.reserve(size_t(nv) * (2 * nu + 2) + 2 * nv + 2);
    std::vector<float> marginal(nv);
    for (uint32_t v = 0; v < nv; ++v) {
        appendDistribution(out, func.data() + size_t(v) * nu, nu);
        marginal[v] = out.back();
    }
    appendDistribution(out, marginal.data(), nv);
    return out;
}

} // namespace urbis
