// Generated city: footprints are valid polygons that overlap neither each other, nor any road
// with its sidewalks, nor the water.
#include "layout/city_layout.h"
#include "layout/street_grid.h"

#include <geos_c.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <vector>

using namespace urbis;

namespace {

double signedArea(const Ring& r) {
    double a = 0;
    for (size_t i = 0; i < r.size(); ++i) {
        const Vec2d &p = r[i], &q = r[(i + 1) % r.size()];
        a += p.x * q.y - q.x * p.y;
    }
    return 0.5 * a;
}

// GEOS geometries of a CityModel, owned by one context.
class Geos {
public:
    Geos() : ctx_(GEOS_init_r()) {}
    ~Geos() {
        for (GEOSGeometry* g : owned_) GEOSGeom_destroy_r(ctx_, g);
        GEOS_finish_r(ctx_);
    }
    Geos(const Geos&) = delete;
    Geos& operator=(const Geos&) = delete;
    GEOSContextHandle_t ctx() const { return ctx_; }

    GEOSGeometry* polygon(const Polygon& p) {
        std::vector<GEOSGeometry*> holes;
        for (const Ring& h : p.holes) holes.push_back(ring(h));
        return keep(GEOSGeom_createPolygon_r(ctx_, ring(p.outer), holes.data(), static_cast<unsigned>(holes.size())));
    }
    GEOSGeometry* solid(const Ring& r) { return keep(GEOSGeom_createPolygon_r(ctx_, ring(r), nullptr, 0)); }
    // The road's carriageway and sidewalks, shrunk by 1 mm so that touching is not overlapping.
    GEOSGeometry* corridor(const Road& road) {
        GEOSGeometry* line = GEOSGeom_createLineString_r(ctx_, sequence(road.centerline, false));
        const double sidewalk = std::max(road.sidewalkLeftWidth, road.sidewalkRightWidth);
        GEOSGeometry* area = GEOSBufferWithStyle_r(ctx_, line, 0.5 * road.width + sidewalk - 1e-3, 8,
                                                   GEOSBUF_CAP_FLAT, GEOSBUF_JOIN_ROUND, 5.0);
        GEOSGeom_destroy_r(ctx_, line);
        return keep(area);
    }
    GEOSGeometry* point(Vec2d p) { return keep(GEOSGeom_createPointFromXY_r(ctx_, p.x, p.y)); }
    GEOSGeometry* line(const std::vector<Vec2d>& pts) { return keep(GEOSGeom_createLineString_r(ctx_, sequence(pts, false))); }

private:
    GEOSCoordSequence* sequence(const std::vector<Vec2d>& pts, bool close) {
        const auto n = static_cast<unsigned>(pts.size() + (close ? 1 : 0));
        GEOSCoordSequence* seq = GEOSCoordSeq_create_r(ctx_, n, 2);
        for (unsigned i = 0; i < n; ++i) {
            const Vec2d& p = pts[i % pts.size()];
            GEOSCoordSeq_setXY_r(ctx_, seq, i, p.x, p.y);
        }
        return seq;
    }
    GEOSGeometry* ring(const Ring& r) { return GEOSGeom_createLinearRing_r(ctx_, sequence(r, true)); }
    GEOSGeometry* keep(GEOSGeometry* g) {
        owned_.push_back(g);
        return g;
    }
    GEOSContextHandle_t ctx_;
    std::vector<GEOSGeometry*> owned_;
};

// An STR tree of the footprints, queried with another geometry's envelope.
class FootprintIndex {
public:
    FootprintIndex(Geos& geos, const std::vector<GEOSGeometry*>& footprints)
        : geos_(geos), tree_(GEOSSTRtree_create_r(geos.ctx(), 10)) {
        for (size_t i = 0; i < footprints.size(); ++i)
            GEOSSTRtree_insert_r(geos.ctx(), tree_, footprints[i], reinterpret_cast<void*>(i));
    }
    ~FootprintIndex() { GEOSSTRtree_destroy_r(geos_.ctx(), tree_); }
    FootprintIndex(const FootprintIndex&) = delete;
    FootprintIndex& operator=(const FootprintIndex&) = delete;
    std::vector<size_t> near(const GEOSGeometry* g) const {
        std::vector<size_t> hits;
        GEOSSTRtree_query_r(
            geos_.ctx(), tree_, g,
            [](void* item, void* out) {
                static_cast<std::vector<size_t>*>(out)->push_back(reinterpret_cast<size_t>(item));
            },
            &hits);
        return hits;
    }

private:
    Geos& geos_;
    GEOSSTRtree* tree_;
};

class LayoutGeometry : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        LayoutParams p;
        p.buildings = 12'000;  // large enough for diagonal and ring arterials and every district
        p.seed = 3;
        city_ = new CityModel(generateCity(p));
    }
    static void TearDownTestSuite() {
        delete city_;
        city_ = nullptr;
    }
    void SetUp() override {
        for (const Building& b : city_->buildings) footprints_.push_back(geos_.polygon(b.footprint));
        index_ = std::make_unique<FootprintIndex>(geos_, footprints_);
    }
    // Footprints whose interior or boundary meets g.
    std::vector<size_t> hits(const GEOSGeometry* g) {
        std::vector<size_t> out;
        for (size_t i : index_->near(g))
            if (GEOSIntersects_r(geos_.ctx(), footprints_[i], g) == 1) out.push_back(i);
        return out;
    }

    static CityModel* city_;
    Geos geos_;
    std::vector<GEOSGeometry*> footprints_;
    std::unique_ptr<FootprintIndex> index_;
};

CityModel* LayoutGeometry::city_ = nullptr;

} // namespace

TEST_F(LayoutGeometry, RingsAreValidAndOriented) {
    size_t withHoles = 0;
    for (size_t i = 0; i < city_->buildings.size(); ++i) {
        const Polygon& p = city_->buildings[i].footprint;
        ASSERT_GE(p.outer.size(), 4u);
        EXPECT_GT(signedArea(p.outer), 0.0) << "outer ring of building " << i << " is not counter-clockwise";
        for (const Ring& h : p.holes) EXPECT_LT(signedArea(h), 0.0) << "hole of building " << i << " is not clockwise";
        char* reason = nullptr;
        ASSERT_EQ(GEOSisValidDetail_r(geos_.ctx(), footprints_[i], 0, &reason, nullptr), 1)
            << "building " << i << ": " << (reason ? reason : "");
        withHoles += p.holes.empty() ? 0 : 1;
    }
    EXPECT_GT(withHoles, 0u);
}

TEST_F(LayoutGeometry, HolesLieInsideTheirOuterRing) {
    for (size_t i = 0; i < city_->buildings.size(); ++i) {
        const Polygon& p = city_->buildings[i].footprint;
        if (p.holes.empty()) continue;
        GEOSGeometry* outer = geos_.solid(p.outer);
        for (const Ring& h : p.holes) {
            Ring ccw(h.rbegin(), h.rend());
            EXPECT_EQ(GEOSContains_r(geos_.ctx(), outer, geos_.solid(ccw)), 1) << "building " << i;
        }
    }
}

TEST_F(LayoutGeometry, FootprintsDoNotTouchEachOther) {
    for (size_t i = 0; i < footprints_.size(); ++i)
        for (size_t j : hits(footprints_[i]))
            EXPECT_EQ(i, j) << "buildings " << i << " and " << j << " meet";
}

TEST_F(LayoutGeometry, FootprintsStayOffRoadsAndSidewalks) {
    size_t arterials = 0;
    for (size_t r = 0; r < city_->roads.size(); ++r) {
        const Road& road = city_->roads[r];
        arterials += road.highway == HighwayClass::Primary && road.centerline.size() != 2 &&
                             road.centerline[0].x != road.centerline[1].x && road.centerline[0].y != road.centerline[1].y
                         ? 1
                         : 0;
        for (size_t i : hits(geos_.corridor(road))) ADD_FAILURE() << "building " << i << " overlaps road " << r;
    }
    EXPECT_GT(arterials, 0u) << "a city this size has a ring road";
}

TEST_F(LayoutGeometry, TreesAndAreasAreNotInBuildings) {
    EXPECT_TRUE(city_->lamps.empty()) << "streets/ places the lamps";
    ASSERT_FALSE(city_->trees.empty());
    ASSERT_FALSE(city_->areas.empty());
    for (const Tree& t : city_->trees) EXPECT_TRUE(hits(geos_.point(t.position)).empty());
    size_t water = 0;
    for (const Area& a : city_->areas) {
        EXPECT_GT(signedArea(a.polygon.outer), 0.0);
        EXPECT_TRUE(hits(geos_.polygon(a.polygon)).empty()) << "area of kind " << int(a.kind);
        water += a.kind == AreaKind::Water ? 1 : 0;
    }
    EXPECT_EQ(water, 1u) << "the river runs through a city this size";
}

TEST_F(LayoutGeometry, EveryRoadOverTheWaterIsABridge) {
    const Area* river = nullptr;
    for (const Area& a : city_->areas)
        if (a.kind == AreaKind::Water) river = &a;
    ASSERT_NE(river, nullptr);
    GEOSGeometry* water = geos_.polygon(river->polygon);
    size_t bridges = 0;
    for (size_t r = 0; r < city_->roads.size(); ++r) {
        const Road& road = city_->roads[r];
        GEOSGeometry* line = geos_.line(road.centerline);
        if (!road.bridge) {
            EXPECT_EQ(GEOSIntersects_r(geos_.ctx(), line, water), 0) << "road " << r << " runs over the water";
            continue;
        }
        ++bridges;
        EXPECT_EQ(road.layer, 1);
        EXPECT_EQ(GEOSIntersects_r(geos_.ctx(), line, water), 1) << "bridge " << r << " spans no water";
        // Each end lands on the bank, about 15 m from the water, where an approach (or a dead end) meets it.
        for (Vec2d end : {road.centerline.front(), road.centerline.back()}) {
            double d = 0;
            GEOSDistance_r(geos_.ctx(), geos_.point(end), water, &d);
            EXPECT_GT(d, 5.0) << "bridge " << r;
        }
    }
    EXPECT_GT(bridges, 3u);
}
