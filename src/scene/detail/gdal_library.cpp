#include "gdal_library.h"

#include <dlfcn.h>

#include <cstring>

namespace gdpn::scene::detail {

namespace {

struct Loaded {
  GdalLibrary functions{};
  std::string why;  // empty when loaded
};

/// Sets `f` to the function `name` of `lib`; false when there is none.
template <typename F>
bool find(void* lib, const char* name, F& f) {
  void* p = dlsym(lib, name);
  if (!p) return false;
  static_assert(sizeof f == sizeof p);
  std::memcpy(&f, &p, sizeof f);  // POSIX: a data pointer from dlsym holds a function's address
  return true;
}

Loaded load() {
  Loaded out;
  void* lib = dlopen(GDPN_GDAL_SONAME, RTLD_NOW | RTLD_LOCAL);  // never closed: GDAL keeps state
  if (!lib) {
    const char* e = dlerror();
    out.why = std::string("GDAL cannot be loaded (") + (e ? e : GDPN_GDAL_SONAME) +
              "); install the package that provides " GDPN_GDAL_SONAME;
    return out;
  }
  GdalLibrary& g = out.functions;
  const char* missing = nullptr;
  auto need = [&](const char* name, auto& f) {
    if (!missing && !find(lib, name, f)) missing = name;
  };
  need("GDALAllRegister", g.allRegister);
  need("GDALOpen", g.open);
  need("GDALClose", g.close);
  need("GDALGetRasterXSize", g.rasterXSize);
  need("GDALGetRasterYSize", g.rasterYSize);
  need("GDALGetRasterCount", g.rasterCount);
  need("GDALGetRasterBand", g.rasterBand);
  need("GDALGetBlockSize", g.blockSize);
  need("GDALGetRasterDataType", g.rasterDataType);
  need("GDALGetDataTypeSizeBytes", g.dataTypeSizeBytes);
  need("GDALRasterIO", g.rasterIO);
  need("GDALGetProjectionRef", g.projectionRef);
  need("GDALGetGeoTransform", g.geoTransform);
  need("CPLPushErrorHandler", g.pushErrorHandler);
  need("CPLPopErrorHandler", g.popErrorHandler);
  need("CPLQuietErrorHandler", g.quietErrorHandler);
  need("CPLGetLastErrorMsg", g.lastErrorMsg);
  need("OSRNewSpatialReference", g.newSpatialReference);
  need("OSRImportFromEPSG", g.importFromEPSG);
  need("OSRSetAxisMappingStrategy", g.setAxisMappingStrategy);
  need("OSRDestroySpatialReference", g.destroySpatialReference);
  need("OCTNewCoordinateTransformation", g.newCoordinateTransformation);
  need("OCTDestroyCoordinateTransformation", g.destroyCoordinateTransformation);
  need("OCTTransform", g.transform);
  if (missing) {
    out.why = std::string("GDAL (" GDPN_GDAL_SONAME ") has no function ") + missing;
    return out;
  }
  g.allRegister();
  return out;
}

}  // namespace

const GdalLibrary* gdal(std::string& why) {
  // loaded once (a function's static is made once, whatever the threads) and never freed:
  // a Geodesy destroyed at exit may still call GDAL
  static const Loaded* const loaded = new Loaded(load());
  if (!loaded->why.empty()) {
    why = loaded->why;
    return nullptr;
  }
  return &loaded->functions;
}

}  // namespace gdpn::scene::detail
