#!/usr/bin/env python3
"""Checks the outputs of `ig bench` (docs/bench.md): results.csv has the
documented header and one row per expected method/knob, every numeric field
is a finite number (knob and bound fields may be empty where the method has
no knob / claims no bound), the reference row has zero error (temporal
error included), the temporal error is non-negative for every row, results.md
holds both tables, error_vs_time.png and temporal_error.png are real PNGs, and
frames.csv / samples.csv have one row per method/knob and frame / sampled
frame, samples.csv with a temporal error exactly where a pair exists.
With --same-errors-as DIR, samples.csv must equal DIR's in every cell but
the timing (frame_ms), row for row once both are sorted by method, knob and
frame: the order the frames were flown in changes no picture. --order
checks frames.csv's row order: sequential (each method and knob's frames
together, in flight order) or interleaved (each frame flown by every method
and knob before the next frame, the first of them rotating).
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
    "upload_bytes_median", "cpu_ms_median", "temporal_pairs", "temporal_error_mean", "temporal_error_max",
    "cores_median", "hidden_boxes_median", "passed_per_pixel_median", "pipelined_frames",
    "pipelined_frame_ms_median", "pipelined_frame_ms_p95", "pipelined_cpu_ms_median",
    "pipelined_latency_ms_median", "pipelined_lod_ms_median",
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


def same_knob(a, b):
    """samples.csv and results.csv write knob values with different digits."""
    if a == "" or b == "":
        return a == b
    return math.isclose(float(a), float(b), rel_tol=1e-5)


def errors_by_frame(out_dir):
    """samples.csv rows without their timing, keyed by method, knob and frame."""
    with open(os.path.join(out_dir, "samples.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    return {(r["method"], r["knob"], r["frame"]): {k: v for k, v in r.items() if k != "frame_ms"} for r in rows}


def check_same_errors(out_dir, other_dir):
    mine, theirs = errors_by_frame(out_dir), errors_by_frame(other_dir)
    if mine.keys() != theirs.keys():
        fail(f"samples.csv of {out_dir} and {other_dir} cover different methods, knobs or frames")
    for key, row in mine.items():
        differ = [c for c in row if row[c] != theirs[key][c]]
        if differ:
            fail(f"samples.csv {key}: {differ[0]} = {row[differ[0]]} here, {theirs[key][differ[0]]} in {other_dir}")
    return len(mine)


def check_order(out_dir, order, variants, frames):
    with open(os.path.join(out_dir, "frames.csv"), newline="") as f:
        rows = [(r["method"], r["knob"], int(r["frame"])) for r in csv.DictReader(f)]
    if order == "sequential":
        blocks = [rows[k * frames:(k + 1) * frames] for k in range(variants)]
        for b in blocks:
            if len({(m, k) for m, k, _ in b}) != 1 or [fr for _, _, fr in b] != sorted(fr for _, _, fr in b):
                fail("frames.csv: a method and knob's frames are not together in flight order")
        return
    blocks = [rows[i * variants:(i + 1) * variants] for i in range(frames)]
    first = [(m, k) for m, k, _ in blocks[0]]
    for i, b in enumerate(blocks):
        if len({fr for _, _, fr in b}) != 1 or len({(m, k) for m, k, _ in b}) != variants:
            fail(f"frames.csv: rows {i * variants + 2}..: not one frame flown by every method and knob")
        rotated = first[i % variants:] + first[:i % variants]
        if [(m, k) for m, k, _ in b] != rotated:
            fail(f"frames.csv: frame {b[0][2]} is not flown in the rotated order")
    if [b[0][2] for b in blocks] != sorted(b[0][2] for b in blocks):
        fail("frames.csv: the frames are not in flight order")


def check_pipelined(d, a, rows, md):
    path = os.path.join(d, "frames_pipelined.csv")
    if not a.pipelined:
        if os.path.exists(path) or any(int(r["pipelined_frames"]) != 0 for r in rows):
            fail("frames were flown pipelined without --pipelined")
        return
    with open(path, newline="") as f:
        frames = list(csv.DictReader(f))
    for r in rows:
        mine = [x for x in frames if x["method"] == r["method"] and same_knob(x["knob"], r["knob_value"])]
        where = f"frames_pipelined.csv ({r['method']} {r['knob_value']})"
        if len(mine) != a.frames or len({x["frame"] for x in mine}) != a.frames:
            fail(f"{where}: {len(mine)} rows, expected each of {a.frames} frames once")
        order = sorted(mine, key=lambda x: int(x["frame"]))
        for k, x in enumerate(order):
            first = k % a.stretch == 0
            if (float(x["interval_ms"]) < 0) != first or (float(x["cpu_ms"]) < 0) != first:
                fail(f"{where} frame {x['frame']}: an interval is set exactly when it is not a stretch's first")
            if not float(x["latency_ms"]) > 0 or not float(x["lod_ms"]) >= 0:
                fail(f"{where} frame {x['frame']}: latency must be > 0 and the LOD step >= 0")
        if int(r["pipelined_frames"]) != a.frames:
            fail(f"{where}: results.csv pipelined_frames {r['pipelined_frames']} != {a.frames}")
        intervals = sorted(float(x["interval_ms"]) for x in mine if float(x["interval_ms"]) >= 0)
        if intervals and not min(intervals) <= float(r["pipelined_frame_ms_median"]) <= max(intervals):
            fail(f"{where}: pipelined_frame_ms_median outside its frames' intervals")
    for needle in ("## Pipelined: frames in flight", "Pipelined (frames in flight)"):
        if needle not in md:
            fail(f"results.md lacks {needle!r}")
    print(f"check_bench_output: {len(frames)} pipelined frames, each once, in stretches of {a.stretch}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out_dir")
    ap.add_argument("--rows", type=int, required=True, help="expected results.csv data rows")
    ap.add_argument("--frames", type=int, required=True, help="frames per method/knob")
    ap.add_argument("--samples", type=int, required=True, help="error samples per method/knob")
    ap.add_argument("--methods", required=True, help="comma-separated methods expected, in order, or all (any)")
    ap.add_argument("--pairs", type=int, required=True, help="temporal error pairs per method/knob")
    ap.add_argument("--order", choices=("sequential", "interleaved"), help="frames.csv's expected row order")
    ap.add_argument("--same-errors-as", metavar="DIR", help="another run whose samples.csv must match but for timing")
    ap.add_argument("--pipelined", action="store_true", help="the run flew every frame pipelined too")
    ap.add_argument("--stretch", type=int, default=10, help="consecutive frames per pipelined stretch")
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
        if int(number(row, "temporal_pairs", where)) != a.pairs:
            fail(f"{where}: temporal_pairs {row['temporal_pairs']} != {a.pairs}")
        if not 0 < number(row, "cores_median", where) <= 64:
            fail(f"{where}: cores_median must be in (0, 64]")
        if not 0 < number(row, "passed_per_pixel_median", where) < 64:
            fail(f"{where}: passed_per_pixel_median must be in (0, 64)")
        if number(row, "hidden_boxes_median", where) < 0:
            fail(f"{where}: hidden_boxes_median must be >= 0")
        if not 0 <= number(row, "temporal_error_mean", where) <= number(row, "temporal_error_max", where):
            fail(f"{where}: temporal error mean must lie in [0, max]")
        if row["method"] == "reference":
            for col in ("horizon_mean_px", "horizon_max_px", "depth_rel_max", "holes_mean", "temporal_error_max"):
                if number(row, col, where) != 0:
                    fail(f"{where}: the reference against itself must have {col} = 0")
    if a.methods != "all" and methods != a.methods.split(","):
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

    for name in ("error_vs_time.png", "temporal_error.png"):
        png = open(os.path.join(d, name), "rb").read()
        if png[:8] != b"\x89PNG\r\n\x1a\n" or png[12:16] != b"IHDR":
            fail(f"{name} is not a PNG")
        w, h = struct.unpack(">II", png[16:24])
        if w < 200 or h < 200 or len(png) < 2000:
            fail(f"{name} looks empty ({w}x{h}, {len(png)} bytes)")

    for name, per_row in (("frames.csv", a.frames), ("samples.csv", a.samples)):
        with open(os.path.join(d, name), newline="") as f:
            n = sum(1 for _ in csv.DictReader(f))
        if n != a.rows * per_row:
            fail(f"{name} has {n} rows, expected {a.rows * per_row}")

    with open(os.path.join(d, "samples.csv"), newline="") as f:
        samples = list(csv.DictReader(f))
    for k, row in enumerate(samples):
        where = f"samples.csv row {k + 1} ({row['method']} frame {row['frame']})"
        if (row["frame_before"] == "") != (row["temporal_error"] == ""):
            fail(f"{where}: frame_before and temporal_error must be both set or both empty")
        if row["temporal_error"] != "":
            if not int(row["frame_before"]) < int(row["frame"]):
                fail(f"{where}: frame_before {row['frame_before']} is not before the sample")
            for col in ("temporal_error", "method_change", "reference_change"):
                if not number(row, col, where) >= 0:
                    fail(f"{where}: {col} must be >= 0")
    for r in rows:
        pairs = [s for s in samples if s["method"] == r["method"] and same_knob(s["knob"], r["knob_value"])
                 and s["temporal_error"] != ""]
        if len(pairs) != int(r["temporal_pairs"]):
            fail(f"{r['method']} {r['knob_value']}: {len(pairs)} samples.csv pairs, results.csv says "
                 f"{r['temporal_pairs']}")
        if pairs:
            mean = sum(float(s["temporal_error"]) for s in pairs) / len(pairs)
            if not math.isclose(mean, float(r["temporal_error_mean"]), rel_tol=1e-4, abs_tol=1e-4):
                fail(f"{r['method']} {r['knob_value']}: temporal_error_mean {r['temporal_error_mean']} is not the "
                     f"mean of its samples.csv pairs ({mean})")
    if "temporal error mean / max" not in md:
        fail("results.md lacks the temporal error column")

    check_pipelined(d, a, rows, md)
    if a.order:
        check_order(d, a.order, a.rows, a.frames)
        print(f"check_bench_output: frames.csv is {a.order}")
    if a.same_errors_as:
        n = check_same_errors(d, a.same_errors_as)
        print(f"check_bench_output: {n} sampled frames match {a.same_errors_as} but for timing")
    print(f"check_bench_output: ok: {len(rows)} rows ({', '.join(methods)}), all numeric fields finite, "
          f"temporal error >= 0 over {a.pairs} pairs each, results.md tables, error_vs_time.png and "
          f"temporal_error.png")


if __name__ == "__main__":
    main()
