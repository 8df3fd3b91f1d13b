#!/usr/bin/env python3
"""How closely two renders of one view agree (the void-fill must-show,
tests/cli/voids.cmake): PSNR over the RGB channels (8-bit, peak 255) and the
share of pixels whose largest channel difference exceeds 16 levels.

  picture_agreement.py A.png B.png [--min-psnr DB] [--max-over16 FRACTION]

Prints one line "psnr_db P over16 F pixels N"; exits 1 when a limit is given
and missed, 2 when a picture cannot be read or the sizes differ. Needs GDAL's
Python bindings and NumPy (Debian: python3-gdal)."""
import argparse
import sys

import numpy as np
from osgeo import gdal


def read_rgb(path):
    ds = gdal.Open(path)
    if ds is None or ds.RasterCount < 3:
        sys.exit(f"{path}: cannot read as an RGB picture")
    # Keep the dataset referenced while its bands are read.
    rgb = np.stack([ds.GetRasterBand(b + 1).ReadAsArray() for b in range(3)], axis=-1)
    return rgb.astype(np.int32)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("a")
    p.add_argument("b")
    p.add_argument("--min-psnr", type=float)
    p.add_argument("--max-over16", type=float)
    args = p.parse_args()
    a, b = read_rgb(args.a), read_rgb(args.b)
    if a.shape != b.shape:
        print(f"sizes differ: {a.shape[1]}x{a.shape[0]} and {b.shape[1]}x{b.shape[0]}", file=sys.stderr)
        return 2
    diff = np.abs(a - b)
    mse = float(np.mean(diff.astype(np.float64) ** 2))
    psnr = 99.0 if mse == 0 else 10.0 * np.log10(255.0 ** 2 / mse)
    over16 = float(np.mean(diff.max(axis=-1) > 16))
    print(f"psnr_db {psnr:.2f} over16 {over16:.4f} pixels {a.shape[0] * a.shape[1]}")
    ok = True
    if args.min_psnr is not None and psnr < args.min_psnr:
        print(f"PSNR {psnr:.2f} dB is below {args.min_psnr} dB")
        ok = False
    if args.max_over16 is not None and over16 > args.max_over16:
        print(f"{100 * over16:.2f} % of pixels differ by more than 16 levels (limit {100 * args.max_over16:.2f} %)")
        ok = False
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
