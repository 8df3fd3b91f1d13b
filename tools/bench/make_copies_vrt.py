#!/usr/bin/env python3
"""Writes a GDAL VRT that tiles one DEM n x n times, neighbours overlapping by
one sample (big_terrain.py's big case: 5 x 5 Sierra copies = 20481 x 20481),
without copying any data: every copy is a SimpleSource of the same file.

usage: make_copies_vrt.py IG SOURCE.tif N OUT.vrt

The source's size and georeferencing come from `IG info SOURCE` (north-up,
no rotation); the mosaic keeps the source's CRS and sample size, its
north-west corner at the source's.
"""
import json
import subprocess
import sys


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    ig, src, n, out = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
    info = json.loads(subprocess.run([ig, "info", src], check=True, capture_output=True, text=True).stdout)
    w, h = info["width"], info["height"]
    b = info["bounds"]
    px = (b["east"] - b["west"]) / w
    py = (b["north"] - b["south"]) / h
    size_x, size_y = (w - 1) * n + 1, (h - 1) * n + 1
    srs = info.get("crs") or ""
    lines = [f'<VRTDataset rasterXSize="{size_x}" rasterYSize="{size_y}">']
    if srs:
        lines.append(f"  <SRS>{srs}</SRS>")
    lines.append(f"  <GeoTransform>{b['west']!r}, {px!r}, 0, {b['north']!r}, 0, {-py!r}</GeoTransform>")
    lines.append('  <VRTRasterBand dataType="Int16" band="1">')
    lines.append("    <NoDataValue>-32768</NoDataValue>")
    for cy in range(n):
        for cx in range(n):
            lines += [
                "    <SimpleSource>",
                f'      <SourceFilename relativeToVRT="0">{src}</SourceFilename>',
                "      <SourceBand>1</SourceBand>",
                f'      <SrcRect xOff="0" yOff="0" xSize="{w}" ySize="{h}"/>',
                f'      <DstRect xOff="{cx * (w - 1)}" yOff="{cy * (h - 1)}" xSize="{w}" ySize="{h}"/>',
                "    </SimpleSource>",
            ]
    lines += ["  </VRTRasterBand>", "</VRTDataset>"]
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"{out}: {size_x} x {size_y} samples ({n} x {n} copies of {src})")


if __name__ == "__main__":
    main()
