#include "terrain/dem_raster.h"

#include "base/input_error.h"
#include "osm/geo_projection.h"

#include <gdal_alg.h>
#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>

namespace urbis {

struct DemRaster::Transforms {
    double toPixel[6];   ///< georeferenced coordinates to (col, row): GDAL's inverse geotransform
    double fromPixel[6];
    std::unique_ptr<OGRCoordinateTransformation> fromWgs84, toWgs84;   ///< null: the raster is in WGS84 degrees
};

namespace {

/// Fills the no-data pixels (NaN) with the mean of their filled 8-neighbours, a ring at a time.
void fillHoles(std::vector<float>& h, int w, int rows) {
    std::vector<float> next;
    bool missing = true;
    while (missing) {
        missing = false;
        next = h;
        for (int r = 0; r < rows; ++r)
            for (int c = 0; c < w; ++c) {
                if (!std::isnan(h[size_t(r) * w + c])) continue;
                double sum = 0;
                int n = 0;
                for (int dr = -1; dr <= 1; ++dr)
                    for (int dc = -1; dc <= 1; ++dc) {
                        const int rr = r + dr, cc = c + dc;
                        if (rr < 0 || cc < 0 || rr >= rows || cc >= w) continue;
                        const float v = h[size_t(rr) * w + cc];
                        if (!std::isnan(v)) sum += v, ++n;
                    }
                if (n > 0) next[size_t(r) * w + c] = float(sum / n);
                else missing = true;
            }
        h.swap(next);
    }
}

/// Catmull-Rom weights of the four samples around fraction f.
void catmullRom(double f, double w[4]) {
    const double f2 = f * f, f3 = f2 * f;
    w[0] = 0.5 * (-f3 + 2 * f2 - f);
    w[1] = 0.5 * (3 * f3 - 5 * f2 + 2);
    w[2] = 0.5 * (-3 * f3 + 4 * f2 + f);
    w[3] = 0.5 * (f3 - f2);
}

} // namespace

DemRaster::DemRaster(const std::string& file) : transforms_(std::make_unique<Transforms>()) {
    GDALAllRegister();
    CPLPushErrorHandler(CPLQuietErrorHandler);
    std::unique_ptr<GDALDataset> ds(GDALDataset::Open(file.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
    CPLPopErrorHandler();
    if (!ds) throw InputError(file + ": GDAL cannot open it as a raster");
    if (ds->GetRasterCount() < 1) throw InputError(file + ": the raster has no band");
    if (ds->GetGeoTransform(transforms_->fromPixel) != CE_None)
        throw InputError(file + ": the raster has no georeferencing (geotransform)");
    if (!GDALInvGeoTransform(transforms_->fromPixel, transforms_->toPixel))
        throw InputError(file + ": the raster's geotransform cannot be inverted");
    width_ = ds->GetRasterXSize();
    height_ = ds->GetRasterYSize();
    GDALRasterBand* band = ds->GetRasterBand(1);
    heights_.resize(size_t(width_) * height_);
    if (band->RasterIO(GF_Read, 0, 0, width_, height_, heights_.data(), width_, height_, GDT_Float32, 0, 0) != CE_None)
        throw InputError(file + ": GDAL cannot read band 1");
    int hasNoData = 0;
    const double noData = band->GetNoDataValue(&hasNoData);
    bool any = false;
    for (float& h : heights_) {
        if ((hasNoData && double(h) == noData) || !std::isfinite(h)) h = NAN;
        else any = true;
    }
    if (!any) throw InputError(file + ": no pixel holds an elevation");
    fillHoles(heights_, width_, height_);

    const OGRSpatialReference* srs = ds->GetSpatialRef();
    if (!srs) throw InputError(file + ": the raster has no coordinate reference system");
    OGRSpatialReference wgs84;
    wgs84.SetWellKnownGeogCS("WGS84");
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    OGRSpatialReference own(*srs);
    own.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    if (!own.IsSame(&wgs84)) {
        transforms_->fromWgs84.reset(OGRCreateCoordinateTransformation(&wgs84, &own));
        transforms_->toWgs84.reset(OGRCreateCoordinateTransformation(&own, &wgs84));
        if (!transforms_->fromWgs84 || !transforms_->toWgs84)
            throw InputError(file + ": GDAL cannot transform its CRS from WGS84");
    }
    // A pixel's metres about the centre, on the same tangent plane as the city's.
    double lon0, lat0, lon1, lat1, lon2, lat2;
    lonLatOf(width_ * 0.5, height_ * 0.5, lon0, lat0);
    lonLatOf(width_ * 0.5 + 1, height_ * 0.5, lon1, lat1);
    lonLatOf(width_ * 0.5, height_ * 0.5 + 1, lon2, lat2);
    const GeoProjection proj({lon0, lat0});
    const Vec2d a = proj.project({lon1, lat1}), b = proj.project({lon2, lat2});
    pixelMetres_ = std::min(std::hypot(a.x, a.y), std::hypot(b.x, b.y));
}

DemRaster::~DemRaster() = default;
DemRaster::DemRaster(DemRaster&&) noexcept = default;

void DemRaster::pixelOf(double lon, double lat, double& col, double& row) const {
    double x = lon, y = lat;
    if (transforms_->fromWgs84) transforms_->fromWgs84->Transform(1, &x, &y);
    GDALApplyGeoTransform(transforms_->toPixel, x, y, &col, &row);
}

void DemRaster::pixelsOf(std::vector<double>& lon, std::vector<double>& lat) const {
    if (transforms_->fromWgs84 && !lon.empty()) transforms_->fromWgs84->Transform(lon.size(), lon.data(), lat.data());
    for (size_t i = 0; i < lon.size(); ++i) {
        double col, row;
        GDALApplyGeoTransform(transforms_->toPixel, lon[i], lat[i], &col, &row);
        lon[i] = col, lat[i] = row;
    }
}

void DemRaster::lonLatOf(double col, double row, double& lon, double& lat) const {
    GDALApplyGeoTransform(transforms_->fromPixel, col, row, &lon, &lat);
    if (transforms_->toWgs84) transforms_->toWgs84->Transform(1, &lon, &lat);
}

float DemRaster::sample(double col, double row, bool bicubic) const {
    // Pixel centres lie at + 0.5; beyond the outer centres the edge pixels' values continue.
    const double x = std::clamp(col - 0.5, 0.0, double(width_ - 1)), y = std::clamp(row - 0.5, 0.0, double(height_ - 1));
    const int i = std::min(int(x), std::max(width_ - 2, 0)), j = std::min(int(y), std::max(height_ - 2, 0));
    const double fx = x - i, fy = y - j;
    auto at = [&](int c, int r) {
        return double(pixel(std::clamp(c, 0, width_ - 1), std::clamp(r, 0, height_ - 1)));
    };
    if (!bicubic)
        return float((at(i, j) * (1 - fx) + at(i + 1, j) * fx) * (1 - fy) + (at(i, j + 1) * (1 - fx) + at(i + 1, j + 1) * fx) * fy);
    double wx[4], wy[4];
    catmullRom(fx, wx);
    catmullRom(fy, wy);
    double sum = 0;
    for (int b = 0; b < 4; ++b)
        for (int a = 0; a < 4; ++a) sum += wx[a] * wy[b] * at(i - 1 + a, j - 1 + b);
    return float(sum);
}

} // namespace urbis
