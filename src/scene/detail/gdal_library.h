#pragma once
/// \file
/// GDAL's C functions that terrain.cpp calls, loaded from the shared library on first use.
/// GDAL pulls in over a hundred libraries (0.1 s of every program's start on the
/// development machine); only a model with a Terrain needs it, so nothing else pays.

#include <gdal.h>
#include <ogr_srs_api.h>

#include <string>

namespace gdpn::scene::detail {

/// Pointers to the GDAL functions gdpn uses, each named as GDAL's without its prefix.
struct GdalLibrary {
  decltype(&::GDALAllRegister) allRegister;
  decltype(&::GDALOpen) open;
  decltype(&::GDALClose) close;
  decltype(&::GDALGetRasterXSize) rasterXSize;
  decltype(&::GDALGetRasterYSize) rasterYSize;
  decltype(&::GDALGetRasterCount) rasterCount;
  decltype(&::GDALGetRasterBand) rasterBand;
  decltype(&::GDALGetBlockSize) blockSize;
  decltype(&::GDALGetRasterDataType) rasterDataType;
  decltype(&::GDALGetDataTypeSizeBytes) dataTypeSizeBytes;
  decltype(&::GDALRasterIO) rasterIO;
  decltype(&::GDALGetProjectionRef) projectionRef;
  decltype(&::GDALGetGeoTransform) geoTransform;
  decltype(&::CPLPushErrorHandler) pushErrorHandler;
  decltype(&::CPLPopErrorHandler) popErrorHandler;
  decltype(&::CPLQuietErrorHandler) quietErrorHandler;
  decltype(&::CPLGetLastErrorMsg) lastErrorMsg;
  decltype(&::OSRNewSpatialReference) newSpatialReference;
  decltype(&::OSRImportFromEPSG) importFromEPSG;
  decltype(&::OSRSetAxisMappingStrategy) setAxisMappingStrategy;
  decltype(&::OSRDestroySpatialReference) destroySpatialReference;
  decltype(&::OCTNewCoordinateTransformation) newCoordinateTransformation;
  decltype(&::OCTDestroyCoordinateTransformation) destroyCoordinateTransformation;
  decltype(&::OCTTransform) transform;
};

/// GDAL, loaded and its drivers registered the first time this is called (thread-safe);
/// null with `why` set when the library or one of its functions cannot be found.
const GdalLibrary* gdal(std::string& why);

}  // namespace gdpn::scene::detail
