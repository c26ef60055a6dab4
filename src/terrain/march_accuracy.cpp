#include "terrain/march_accuracy.h"

#include <algorithm>
#include <cmath>

namespace urbis {
namespace {

/// Metres by which a hit may differ from the reference's and still be the same intersection.
constexpr double kSameHit = 1.0;

/// The point at distance t along a ray.
Vec3f along(const Ray& ray, float t) { return ray.origin + ray.dir * t; }

} // namespace

MarchAccuracy marchAccuracy(const TerrainRecord& terrain, const float* data, const std::vector<Ray>& rays,
                            const std::vector<float>& t, const std::vector<float>& reference) {
    MarchAccuracy a;
    for (size_t b = 0; b < kHdeBands; ++b) a.byDistance[b].from = kHdeBandEdges[b], a.byDistance[b].to = kHdeBandEdges[b + 1];
    size_t both = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
        const double len = std::sqrt(double(dot(rays[i].dir, rays[i].dir)));
        const bool hit = t[i] >= 0.0f, refHit = reference[i] >= 0.0f;
        if (hit) {
            ++a.hits;
            const Vec3f p = along(rays[i], t[i]);
            const double hde = std::fabs(double(p.y) - double(terrainHeight(terrain, data, p.x, p.z)));
            a.meanHde += hde;
            a.maxHde = std::max(a.maxHde, hde);
            const double distance = double(t[i]) * len;
            for (HdeBand& band : a.byDistance)
                if (distance >= band.from && distance < band.to) {
                    ++band.hits;
                    band.meanHde += hde;
                    band.maxHde = std::max(band.maxHde, hde);
                }
        }
        if (refHit && (!hit || (double(t[i]) - double(reference[i])) * len > kSameHit)) ++a.missed;
        else if (hit && (!refHit || (double(reference[i]) - double(t[i])) * len > kSameHit)) ++a.extra;
        else if (hit && refHit) {
            const double ide = std::fabs(double(t[i]) - double(reference[i])) * len;
            a.meanIde += ide;
            a.maxIde = std::max(a.maxIde, ide);
            ++both;
        }
    }
    a.meanHde /= double(std::max<size_t>(a.hits, 1));
    for (HdeBand& band : a.byDistance) band.meanHde /= double(std::max<size_t>(band.hits, 1));
    a.meanIde /= double(std::max<size_t>(both, 1));
    return a;
}

} // namespace urbis
