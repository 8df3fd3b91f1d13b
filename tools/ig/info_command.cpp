// `ig info FILE [options]`: load a DEM and print what the IG sees as JSON.

#include <fcntl.h>
#include <unistd.h>

#include <charconv>
#include <cstdio>
#include <cmath>
#include <exception>
#include <iostream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cli_args.h"
#include "ig/commands.h"
#include "terrain/dem_loader.h"
#include "water/water_file.h"
#include "water/water_setup.h"

namespace ig::app {

namespace {

constexpr const char* kUsage =
    "usage: ig info FILE|FOLDER [--encoding auto|terrain-rgb|png16|gdal] [--scale S] [--offset O]\n"
    "                    [--spacing M] [--fill-max-distance N] [--fill-smoothing N]\n"
    "                    [--water auto|off|FILE] [--water-level-attribute NAME]\n"
    "Loads a DEM (GeoTIFF, SRTM .hgt, USGS DEM, ESRI ASCII grid, any single-band GDAL\n"
    "raster or VRT, 16-bit PNG or terrain-RGB PNG; a FOLDER is a mosaic of the DEM tiles\n"
    "in it) and prints one JSON object: size, spacing in metres, min/max/mean height,\n"
    "filled nodata samples (nodata_count) and how they were filled (void_fill: GDAL's\n"
    "GDALFillNodata, its settings, deep_count = voids beyond its search distance),\n"
    "CRS, corner coordinates, for a folder the tile counts, and the water terrain.water\n"
    "finds or reads (auto by default: the sea and lakes an SRTM edit left; off; or a\n"
    "GDAL raster or OGR polygon FILE): source, bodies, area, each body's level.\n"
    "Exit status: 0 ok, 1 the file could not be loaded, 2 bad arguments.\n";

double parse_number(const std::string& option, const std::string& text) {
  double v = 0.0;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (!text.empty() && *first == '+') ++first;
  const auto res = std::from_chars(first, last, v);
  if (text.empty() || res.ec != std::errc() || res.ptr != last || !std::isfinite(v))
    throw UsageError(option + " needs a number, got '" + text + "'");
  return v;
}

// libpng (under OpenImageIO) prints its own "libpng error: ..." lines for a
// corrupt PNG; `ig info` promises exactly one error line, so file descriptor
// 2 points at /dev/null while the DEM loads (the loader reports every
// failure through DemError anyway). Only the CLI does this, never the library.
class SilenceStderr {
 public:
  SilenceStderr() {
    std::fflush(stderr);
    saved_ = ::dup(2);
    const int null_fd = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (saved_ >= 0 && null_fd >= 0) ::dup2(null_fd, 2);
    if (null_fd >= 0) ::close(null_fd);
  }
  ~SilenceStderr() {
    std::fflush(stderr);
    if (saved_ >= 0) {
      ::dup2(saved_, 2);
      ::close(saved_);
    }
  }
  SilenceStderr(const SilenceStderr&) = delete;
  SilenceStderr& operator=(const SilenceStderr&) = delete;

 private:
  int saved_ = -1;
};

// The DEM file and its load options from the command line; UsageError (one
// line, no usage text) on a mistake.
std::string parse_args(const std::vector<std::string>& args, terrain::DemLoadOptions& opts,
                       options::WaterOptions& water) {
  CLI::App app("ig info");
  std::vector<std::string> files;
  std::optional<std::string> encoding, scale, offset, spacing, fill_distance, fill_smoothing, water_source,
      level_attribute;
  app.add_option("file", files, "the DEM file, or a folder of DEM tiles read as one mosaic")->option_text("FILE|FOLDER");
  app.add_option("--encoding", encoding,
                 "how to decode: auto (default; PNGs by their layout, else GDAL), png16 (metres = value * scale "
                 "+ offset), terrain-rgb (metres = -10000 + (R*65536 + G*256 + B) * 0.1), gdal")
      ->option_text("E");
  app.add_option("--scale", scale, "png16: metres per count (default 1)")->option_text("S");
  app.add_option("--offset", offset, "png16: metres added after scaling (default 0)")->option_text("O");
  app.add_option("--spacing", spacing, "sample spacing in metres (images carry none: default 1)")->option_text("M");
  app.add_option("--fill-max-distance", fill_distance,
                 "how far (samples, 1..1024) the void fill searches for valid samples (gdal_fillnodata.py -md; "
                 "default 400)")
      ->option_text("N");
  app.add_option("--fill-smoothing", fill_smoothing,
                 "smoothing passes over filled samples, 0..32 (gdal_fillnodata.py -si; default 2)")
      ->option_text("N");
  app.add_option("--water", water_source,
                 "where the water is: auto (default: the sea and lakes an SRTM edit left in the DEM), off, or a "
                 "water FILE (any GDAL raster, non-zero = water, or OGR layer of polygons)")
      ->option_text("auto|off|FILE");
  app.add_option("--water-level-attribute", level_attribute,
                 "with a polygon FILE: the numeric attribute holding each polygon's level in metres (default: "
                 "from the DEM)")
      ->option_text("NAME");
  try {
    parse_command_line(app, args);
  } catch (const UsageError& e) {
    const std::string what = e.what();
    throw UsageError(what.rfind("unknown option", 0) == 0 ? what + " (try ig info --help)" : what);
  }
  if (encoding) {
    if (*encoding != "auto" && *encoding != "terrain-rgb" && *encoding != "png16" && *encoding != "gdal")
      throw UsageError("--encoding must be auto, terrain-rgb, png16 or gdal, got '" + *encoding + "'");
    opts.encoding = *encoding;
  }
  if (scale) opts.scale = parse_number("--scale", *scale);
  if (offset) opts.offset = parse_number("--offset", *offset);
  if (spacing) {
    const double s = parse_number("--spacing", *spacing);
    if (!(s > 0)) throw UsageError("--spacing must be a positive number of metres");
    opts.spacing_m = s;
  }
  // An integer within limits, else a usage error naming the option.
  auto whole_number = [](const std::string& option, const std::string& text, int lo, int hi) {
    const double v = parse_number(option, text);
    if (v != std::floor(v) || v < lo || v > hi)
      throw UsageError(option + " must be an integer in " + std::to_string(lo) + ".." + std::to_string(hi) +
                       ", got '" + text + "'");
    return int(v);
  };
  using VoidFill = options::VoidFillOptions;
  if (fill_distance)
    opts.void_fill.max_distance = whole_number("--fill-max-distance", *fill_distance, 1, VoidFill::kMaxVoidSearch);
  if (fill_smoothing)
    opts.void_fill.smoothing_iterations =
        whole_number("--fill-smoothing", *fill_smoothing, 0, VoidFill::kMaxVoidSmoothing);
  if (water_source) {
    if (*water_source == "auto" || *water_source == "off") {
      water.source = *water_source == "auto" ? options::WaterSource::Auto : options::WaterSource::Off;
    } else if (water_source->empty()) {
      throw UsageError("--water needs auto, off or a file's path");
    } else {
      water.source = options::WaterSource::File;
      water.file = *water_source;
    }
  }
  if (level_attribute) {
    if (water.source != options::WaterSource::File)
      throw UsageError("--water-level-attribute needs --water FILE (a polygon layer)");
    water.level_attribute = *level_attribute;
  }
  if (files.size() > 1) throw UsageError("more than one FILE given ('" + files[0] + "', '" + files[1] + "')");
  if (files.empty()) throw UsageError("missing FILE (usage: ig info FILE [options]; see --help)");
  return files[0];
}

}  // namespace

int run_info_command(const std::vector<std::string>& args) {
  terrain::DemLoadOptions opts;
  options::WaterOptions water;
  std::string file;
  try {
    file = parse_args(args, opts, water);
  } catch (const HelpRequested& h) {
    std::cout << kUsage << "\n" << h.options;
    return 0;
  } catch (const UsageError& e) {
    std::cerr << "ig info: " << e.what() << "\n";
    return 2;
  }

  try {
    terrain::Heightfield hf;
    std::shared_ptr<const water::WaterMap> found;
    {
      SilenceStderr quiet;
      hf = terrain::load_dem(file, opts);
      found = water::place_water(hf, water);
    }
    std::cout << terrain::dem_info_json(hf, found.get(), water.source == options::WaterSource::Off) << "\n";
    std::cout.flush();
    return std::cout ? 0 : 1;
  } catch (const std::exception& e) {  // DemError, and e.g. std::bad_alloc
    std::cerr << "ig info: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace ig::app
