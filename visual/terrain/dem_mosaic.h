#pragma once
// A folder of DEM tiles as one raster: the tiles are mosaicked by GDAL into
// an in-memory VRT (what gdalbuildvrt does), which the DEM loader then reads
// like any file. Tiles may differ in size and resolution (the finest is
// kept, others resampled bilinearly); tiles in another CRS than the first
// are reprojected to it through a warped VRT; samples no tile covers are
// nodata (filled and counted by the loader). docs/terrain-data.md.

#include <string>
#include <vector>

namespace ig::terrain {

// Extensions read as DEM tiles in a folder (lower case, with the dot). Other
// files (READMEs, .aux.xml, .prj ...) are ignored and listed.
const std::vector<std::string>& dem_tile_extensions();

class DemMosaic {
 public:
  // Builds the mosaic of the tiles in `folder` (not recursive). Throws
  // DemError naming the folder or the offending tile: no tiles, a tile GDAL
  // cannot open, a tile with more than one band or without georeferencing,
  // a CRS that cannot be transformed to the first tile's.
  explicit DemMosaic(const std::string& folder);
  ~DemMosaic();  // removes the in-memory VRTs
  DemMosaic(const DemMosaic&) = delete;
  DemMosaic& operator=(const DemMosaic&) = delete;

  const std::string& vrt_path() const { return vrt_path_; }  // a /vsimem/ path GDAL opens
  int tile_count() const { return int(tiles_.size()); }
  int reprojected_count() const { return reprojected_; }
  const std::vector<std::string>& tiles() const { return tiles_; }
  const std::vector<std::string>& ignored_files() const { return ignored_; }

 private:
  std::string vrt_path_;
  std::vector<std::string> tiles_, ignored_, memory_files_, sources_for_vrt_;
  int reprojected_ = 0;
};

}  // namespace ig::terrain
