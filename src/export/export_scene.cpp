#include "export/export_scene.h"

namespace urbis {

size_t ExportNode::triangleCount() const {
    size_t n = 0;
    for (const ExportPrimitive& p : primitives) n += p.triangles.size();
    return n;
}

Bounds3f ExportNode::bounds() const {
    Bounds3f b;
    for (const ExportPrimitive& p : primitives)
        for (const Triangle& t : p.triangles) b.extend(primBounds(t));
    return b;
}

size_t ExportScene::triangleCount() const {
    size_t n = 0;
    for (const ExportNode& node : nodes) n += node.triangleCount();
    return n;
}

} // namespace urbis
