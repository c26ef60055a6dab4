// A growing set of stored triangles with their per-triangle records (host).
#pragma once

#include "scene/triangle.h"

#include <vector>

namespace urbis {

struct TriangleMesh {
    std::vector<Triangle> triangles;
    std::vector<TriangleInfo> info;

    void add(const Triangle& t, TriangleInfo i) {
        triangles.push_back(t);
        info.push_back(i);
    }
    void append(const TriangleMesh& other) {
        triangles.insert(triangles.end(), other.triangles.begin(), other.triangles.end());
        info.insert(info.end(), other.info.begin(), other.info.end());
    }
    size_t size() const { return triangles.size(); }
};

} // namespace urbis
