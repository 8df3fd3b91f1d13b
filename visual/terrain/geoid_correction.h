#pragma once
// Ellipsoidal DEM heights to heights above the EGM96 geoid
// (docs/terrain-data.md "Vertical datum"). The IG works
// in heights above mean sea level, as CIGI and FGNetFDM altitudes are; SRTM
// heights are above EGM96 already, but some DEMs (lidar, GNSS surveys) give
// heights above the WGS 84 ellipsoid, 20-40 m off over the Sierra. With
// terrain.vertical_datum "ellipsoid" the loader subtracts the geoid
// undulation N (h_ortho = h_ellipsoid - N) from every valid sample before
// voids are filled, in the whole load and in every paged tile alike.
//
// N comes from PROJ's EGM96 grid (egm96_15.gtx, Debian's proj-data, found
// on PROJ's search path), read through GDAL and sampled bilinearly at the
// nodes of a coarse grid over the DEM (every `step` samples; the 15' grid
// is far coarser than that), then bilinear between the nodes. No GL.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace ig::terrain {

class GeoidCorrection {
 public:
  // grid_to_crs maps the DEM's (i, j) (south-up sample centres) to its CRS
  // (GeoReference::grid_to_crs). Throws std::runtime_error with the reason
  // when the EGM96 grid is not found or the CRS cannot reach WGS 84.
  GeoidCorrection(const std::array<double, 6>& grid_to_crs, const std::string& crs_wkt, int width, int height,
                  int step = 32);

  // Geoid undulation N in metres at DEM sample (i, j) (fractions allowed).
  double undulation(double i, double j) const;
  // heights (w x h, row-major, row 0 = sample row y0) -= N, for valid
  // samples only (state == nullptr: all valid; else state[k] != 0).
  void to_orthometric(int x0, int y0, int w, int h, float* heights, const std::uint8_t* state) const;
  const std::string& grid_file() const { return grid_file_; }

  // The EGM96 grid on PROJ's search path ("" when absent).
  static std::string find_grid_file();

 private:
  int step_, nx_, ny_;
  int width_ = 0, height_ = 0;
  std::vector<double> nodes_;  // N at samples (k * step, l * step), clamped to the DEM; row-major
  std::string grid_file_;
};

}  // namespace ig::terrain
