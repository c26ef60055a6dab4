// DemRaster in a build without GDAL (-DURBIS_GDAL=OFF, for machines that lack GDAL's libraries, such
// as the GPU machine, which reaches no package registry): every DEM is refused with a clear message,
// so no raster ever exists and the other members are never reached.
#include "terrain/dem_raster.h"

#include "base/input_error.h"

namespace urbis {

struct DemRaster::Transforms {};

DemRaster::DemRaster(const std::string& file) {
    throw InputError(file + ": this urbis was built without GDAL (-DURBIS_GDAL=OFF), so it reads no elevation rasters");
}

DemRaster::~DemRaster() = default;
DemRaster::DemRaster(DemRaster&&) noexcept = default;

void DemRaster::pixelOf(double, double, double& col, double& row) const { col = row = 0.0; }
void DemRaster::pixelsOf(std::vector<double>&, std::vector<double>&) const {}
void DemRaster::lonLatOf(double, double, double& lon, double& lat) const { lon = lat = 0.0; }
float DemRaster::sample(double, double, bool) const { return 0.0f; }

} // namespace urbis
