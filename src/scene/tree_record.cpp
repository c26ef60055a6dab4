#include "scene/tree_record.h"

#include "scene/tree_shape.h"

#include <cmath>

namespace urbis {

Bounds3f primBounds(const TreeRecord& tree) {
    const Bounds3f local = treeLocalBounds(treeShapeOf(tree));
    // The intersector works in tree coordinates (world minus base): a millimetre and a relative margin
    // keep every hit inside the world box.
    const Vec3f lo = tree.base + local.lo, hi = tree.base + local.hi;
    const float pad = 1e-3f + 1e-6f * maxComponent(vmax(vmax(hi, -hi), vmax(lo, -lo)));
    return {lo - Vec3f{pad, pad, pad}, hi + Vec3f{pad, pad, pad}};
}

} // namespace urbis
