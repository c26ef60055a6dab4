// A digital elevation model read with GDAL: any raster it opens (GeoTIFF, a .vrt mosaic, ...) in any
// CRS it can transform from WGS84, no-data holes filled, sampled at longitudes and latitudes.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace urbis {

/// One band of elevations (metres) and the transform from WGS84 to its pixels.
class DemRaster {
public:
    /// Reads band 1 of `file`; InputError (naming the file) if GDAL cannot open it, it has no
    /// georeferencing, or no pixel holds data. No-data pixels take the mean of their filled
    /// neighbours, ring by ring inwards from the data (a diffusion fill).
    explicit DemRaster(const std::string& file);
    ~DemRaster();
    DemRaster(DemRaster&&) noexcept;

    /// The pixel position (column, row; pixel centres at + 0.5) of a WGS84 point, degrees.
    void pixelOf(double lon, double lat, double& col, double& row) const;
    /// pixelOf for many points at once, in place: longitudes become columns, latitudes rows. One
    /// call of GDAL's transformation, which is not to be shared between threads.
    void pixelsOf(std::vector<double>& lon, std::vector<double>& lat) const;
    /// The WGS84 point (degrees) of pixel position (col, row).
    void lonLatOf(double col, double row, double& lon, double& lat) const;
    /// The elevation at pixel position (col, row), bilinear or Catmull-Rom bicubic between the
    /// pixel centres, the edge pixels' beyond them.
    float sample(double col, double row, bool bicubic) const;
    /// The value of pixel (c, r) as filled.
    float pixel(int c, int r) const { return heights_[size_t(r) * width_ + c]; }
    int width() const { return width_; }
    int height() const { return height_; }
    /// Metres a pixel spans (the smaller side), about the raster's centre.
    double pixelMetres() const { return pixelMetres_; }

private:
    struct Transforms;
    std::unique_ptr<Transforms> transforms_;
    std::vector<float> heights_;
    int width_ = 0, height_ = 0;
    double pixelMetres_ = 0;
};

} // namespace urbis
