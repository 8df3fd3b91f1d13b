#!/usr/bin/env python3
"""Checks the outputs of `ig bench` (docs/bench.md): results.csv has the
documented header and one row per expected method/knob, every numeric field
is a finite number (knob and bound fields may be empty where the method has
no knob / claims no bound), the reference row has zero error, results.md
holds both tables, error_vs_time.png is a real PNG, and frames.csv /
samples.csv have one row per method/knob and frame / sampled frame.
Prints what it checked; exit 1 on the first failure."""
import argparse
import csv
import math
import os
import struct
import sys

COLUMNS = [
    "method", "knob_name", "knob_value", "knob_unit", "is_default", "build_ms", "frames",
    "frame_ms_median", "frame_ms_p95", "lod_ms_median", "triangles_median", "error_samples",
    "horizon_mean_px", "horizon_max_px", "depth_rel_p95", "depth_rel_max", "psnr_db",
    "holes_mean", "hole_fraction", "interior_holes_mean", "enclosed_holes_mean", "bound_px_median",
    "bound_px_max", "vs_invocations_median", "fs_invocations_median", "primitives_median", "draw_calls_median",
    "upload_bytes_median", "cpu_ms_median",
]
TEXT = {"method", "knob_name", "knob_unit"}
MAY_BE_EMPTY = {"knob_value", "bound_px_median", "bound_px_max"}


def fail(msg):
    print("check_bench_output: FAIL: " + msg)
    sys.exit(1)


def number(row, col, where):
    v = row[col]
    try:
        x = float(v)
    except ValueError:
        fail(f"{where}: {col} = {v!r} is not a number")
    if not math.isfinite(x):
        fail(f"{where}: {col} = {v!r} is not finite")
    return x


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out_dir")
    ap.add_argument("--rows", type=int, required=True, help="expected results.csv data rows")
    ap.add_argument("--frames", type=int, required=True, help="frames per method/knob")
    ap.add_argument("--samples", type=int, required=True, help="error samples per method/knob")
    ap.add_argument("--methods", required=True, help="comma-separated methods expected, in order")
    a = ap.parse_args()
    d = a.out_dir

    with open(os.path.join(d, "results.csv"), newline="") as f:
        reader = csv.DictReader(f)
        if reader.fieldnames != COLUMNS:
            fail(f"results.csv header {reader.fieldnames} != {COLUMNS}")
        rows = list(reader)
    if len(rows) != a.rows:
        fail(f"results.csv has {len(rows)} rows, expected {a.rows}")
    methods = []
    for k, row in enumerate(rows):
        where = f"results.csv row {k + 1} ({row['method']})"
        if row["method"] not in methods:
            methods.append(row["method"])
        for col in COLUMNS:
            if col in TEXT or (col in MAY_BE_EMPTY and row[col] == ""):
                continue
            number(row, col, where)
        if (row["knob_name"] == "") != (row["knob_value"] == ""):
            fail(f"{where}: knob_name and knob_value must be both set or both empty")
        if (row["bound_px_median"] == "") != (row["bound_px_max"] == ""):
            fail(f"{where}: bound_px_median and bound_px_max must be both set or both empty")
        if int(number(row, "frames", where)) != a.frames:
            fail(f"{where}: frames {row['frames']} != {a.frames}")
        if int(number(row, "error_samples", where)) != a.samples:
            fail(f"{where}: error_samples {row['error_samples']} != {a.samples}")
        if not number(row, "frame_ms_median", where) > 0:
            fail(f"{where}: frame_ms_median must be > 0")
        if number(row, "frame_ms_p95", where) < number(row, "frame_ms_median", where):
            fail(f"{where}: p95 below the median")
        if number(row, "horizon_max_px", where) < number(row, "horizon_mean_px", where):
            fail(f"{where}: horizon max below its mean")
        if not number(row, "cpu_ms_median", where) > 0:
            fail(f"{where}: cpu_ms_median must be > 0")
        if not number(row, "triangles_median", where) > 0:
            fail(f"{where}: no triangles drawn")
        if not 0 <= number(row, "hole_fraction", where) <= 1:
            fail(f"{where}: hole_fraction outside [0, 1]")
        if row["method"] == "reference":
            for col in ("horizon_mean_px", "horizon_max_px", "depth_rel_max", "holes_mean"):
                if number(row, col, where) != 0:
                    fail(f"{where}: the reference against itself must have {col} = 0")
    if methods != a.methods.split(","):
        fail(f"methods {methods} != {a.methods.split(',')}")
    defaults = [r["method"] for r in rows if r["is_default"] == "1"]
    if sorted(defaults) != sorted(methods):
        fail(f"each method needs exactly one default row, got {defaults}")

    md = open(os.path.join(d, "results.md")).read()
    for needle in ("## Error against run time", "## Matched horizon error", "| method | knob |", "- renderer: ",
                   "- command: `ig bench"):
        if needle not in md:
            fail(f"results.md lacks {needle!r}")
    if sum(1 for r in rows if r["method"] == "twolevel") > 1 and \
            "## Matched horizon error at every two-level setting" not in md:
        fail("results.md lacks the per-setting matched table of a two-level sweep")
    for m in methods:
        if f"| {m} |" not in md:
            fail(f"results.md has no row for {m}")

    png = open(os.path.join(d, "error_vs_time.png"), "rb").read()
    if png[:8] != b"\x89PNG\r\n\x1a\n" or png[12:16] != b"IHDR":
        fail("error_vs_time.png is not a PNG")
    w, h = struct.unpack(">II", png[16:24])
    if w < 200 or h < 200 or len(png) < 2000:
        fail(f"error_vs_time.png looks empty ({w}x{h}, {len(png)} bytes)")

    for name, per_row in (("frames.csv", a.frames), ("samples.csv", a.samples)):
        with open(os.path.join(d, name), newline="") as f:
            n = sum(1 for _ in csv.DictReader(f))
        if n != a.rows * per_row:
            fail(f"{name} has {n} rows, expected {a.rows * per_row}")

    print(f"check_bench_output: ok: {len(rows)} rows ({', '.join(methods)}), all numeric fields finite, "
          f"results.md tables, error_vs_time.png {w}x{h}")


if __name__ == "__main__":
    main()
