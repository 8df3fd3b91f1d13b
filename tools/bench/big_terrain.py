#!/usr/bin/env python3
"""Big-terrain benchmark: `ig run` on DEMs beyond one GL texture,
made at bench time under /tmp and deleted after (nothing large is kept).

usage: IG_DEM_DIR=... tools/bench/big_terrain.py BUILD_DIR OUT.md [--duration S] [--size WxH]

Cases: the Sierra DEM itself (4097², fits one texture: the reference row,
flying over its interior around lat 36.7, lon -118.3), and a VRT of 5 x 5
Sierra copies overlapping by one sample (20481², beyond the 16384 texture
limit: overview + height window), flying across the corner where four
copies meet (lat 36.0, lon -117.0: tile boundaries in both directions).
With --cases including sierra_8x8_32769: 8 x 8 copies (32769², the size
of the synthetic 32769² case below, made the cheap way; its float
heights alone are 4.3 GB, so they are paged from the VRT by the tile
cache within terrain.memory_budget_mb, docs/terrain-data.md). With
synthetic_tiles_32769: the synthetic fractal refined to 32769^2 at 15 m and
written as a folder of 8 x 8 GeoTIFF tiles sharing edges (make_synthetic_tiles;
about 1 GB of memory and a few minutes to make). All fly 250 kt
(128.6 m/s) at 50-150 m above ground, heading 135. --budget-mb sets
terrain.memory_budget_mb (default: the scenario default, 2048; a DEM whose
float heights exceed it is paged). Measured per case, written to OUT.md as a
Markdown table: load-to-first-frame time, peak resident memory
(/usr/bin/time -v), bytes per sample, frame-time p99, the height window's
uploads (MB per second of flight, largest per frame), tiles paged in by the
background thread per second of wall time, and frames that waited on I/O
(paged: frames with a synchronous page-in, summary.json "paging").

Imagery: with --cases including sierra_4097_ortho,
an RGB GeoTIFF --imagery-scale (default 6) times finer than the Sierra DEM
(24582^2 at 6: 1.8 GB of RGB; tiled, DEFLATE; red the height, green/blue a
pixel-level pattern) is made at bench time by imagery_tool (BUILD/bin) and
draped over the Sierra DEM: beyond the texture limit it is paged from GDAL
within terrain.imagery_budget_mb (--imagery-budget-mb, default the scenario
default). Its columns: the imagery cache's budget and peak, tiles paged in
per second, the window's held moves (and frames holding), and frames that
waited on an imagery tile (0 by design), from summary.json "paging.imagery".
"""
import argparse
import csv
import json
import os
import re
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SPEED = 128.6  # m/s = 250 kt


def flight(duration_s, centre):
    # Straight line heading 135 deg through centre, centred on it: (lat, lon),
    # or ("local", x, y) in terrain-local metres.
    half = SPEED * duration_s / 2
    if centre[0] == "local":
        d = half * 0.7071
        agl = [50, 150, 80, 120, 60]
        keys = [{"t": duration_s * k / 4, "position": [centre[1] - d + 2 * d * k / 4, centre[2] + d - 2 * d * k / 4, agl[k]],
                 "hpr": [135, -3, 0]} for k in range(5)]
        return {"frame": "local", "altitude": "agl", "keys": keys}
    dn = half / 111000.0 * 0.7071
    de = half / 90060.0 * 0.7071  # metres per degree of longitude at 36 deg N
    keys = []
    n = 5
    agl = [50, 150, 80, 120, 60]
    for k in range(n):
        f = k / (n - 1)
        lat = centre[0] + dn - 2 * dn * f
        lon = centre[1] - de + 2 * de * f
        keys.append({"t": duration_s * f, "position": [lat, lon, agl[k]], "hpr": [135, -3, 0]})
    return {"frame": "geodetic", "altitude": "agl", "keys": keys}


def p99(values):
    v = sorted(values)
    return v[min(len(v) - 1, int(0.99 * len(v)))] if v else 0.0


def run_case(ig, name, dem, centre, out_dir, args, imagery=None):
    w, h = args.size
    terrain_spec = {"file": dem}
    if args.budget_mb:
        terrain_spec["memory_budget_mb"] = args.budget_mb
    render = {"width": w, "height": h, "fov_y_deg": 60}
    if imagery:
        render["imagery"] = imagery
        if args.imagery_budget_mb:
            terrain_spec["imagery_budget_mb"] = args.imagery_budget_mb
    scenario = {"name": name, "terrain": terrain_spec, "render": render,
                "path": flight(args.duration, centre), "time": {"step_s": args.step, "duration_s": args.duration}}
    sc = os.path.join(out_dir, name + ".json")
    with open(sc, "w") as f:
        json.dump(scenario, f)
    run_dir = os.path.join(out_dir, "run_" + name)
    cmd = ["/usr/bin/time", "-v", ig, "run", sc, "--out", run_dir, "--headless", "--quiet"]
    t0 = time.monotonic()
    p = subprocess.run(cmd, capture_output=True, text=True)
    elapsed = time.monotonic() - t0
    if p.returncode != 0:
        return {"name": name, "error": (p.stderr.strip().splitlines() or ["exit %d" % p.returncode])[0]}
    rss_kb = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", p.stderr).group(1))
    summary = json.load(open(os.path.join(run_dir, "summary.json")))
    rows = list(csv.DictReader(open(os.path.join(run_dir, "frames.csv"))))
    walls = [float(r["wall_ms"]) for r in rows]
    uploads = [int(r["upload_bytes"]) for r in rows]
    terrain = summary["terrain"]
    samples = terrain["width"] * terrain["height"]
    return {
        "name": name,
        "size": "%dx%d" % (terrain["width"], terrain["height"]),
        "load_s": terrain["load_ms"] / 1000,
        # Process start to the end of frame 1: all but the later frames' wall time.
        "first_frame_s": elapsed - sum(walls[1:]) / 1000,
        "rss_mb": rss_kb / 1024,
        "bytes_per_sample": rss_kb * 1024 / samples,
        "frames": len(rows),
        "p99_ms": summary["frame_time"]["p99_ms"],
        "median_ms": summary["frame_time"]["median_ms"],
        "upload_mb_s": sum(uploads[1:]) / 1e6 / max(args.duration - args.step, 1e-9),
        "upload_max_kb": max(uploads[1:] or [0]) / 1e3,
        "lod_p99_ms": p99([float(r["lod_ms"]) for r in rows[1:]]),
        "terrain_p99_ms": p99([float(r["terrain_ms"]) for r in rows[1:]]),
        "elapsed_s": elapsed,
        "paging": summary.get("paging"),
        # Live paging: frames whose Level1 kept the last square while tiles were read.
        "level1_held": sum(1 for r in rows if r.get("level1_held") == "1"),
        "imagery_held_frames": sum(1 for r in rows if int(r.get("imagery_held") or 0) > 0),
    }


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("out")
    ap.add_argument("--duration", type=float, default=40.0)
    ap.add_argument("--step", type=float, default=0.1)
    ap.add_argument("--size", default="640x480")
    ap.add_argument("--budget-mb", type=int, default=0, help="terrain.memory_budget_mb (0: the default)")
    ap.add_argument("--cases", default="sierra_4097,sierra_5x5_20481",
                    help="comma-separated: sierra_4097, sierra_5x5_20481, sierra_8x8_32769, synthetic_tiles_32769, sierra_4097_ortho")
    ap.add_argument("--imagery-scale", type=int, default=6, help="imagery pixels per DEM sample (sierra_4097_ortho)")
    ap.add_argument("--imagery-budget-mb", type=int, default=0, help="terrain.imagery_budget_mb (0: the default)")
    args = ap.parse_args()
    args.size = tuple(int(v) for v in args.size.split("x"))
    dem_dir = os.environ.get("IG_DEM_DIR")
    if not dem_dir:
        sys.exit("IG_DEM_DIR not set")
    ig = os.path.join(args.build, "bin", "ig")
    sierra = os.path.join(dem_dir, "sierra_nevada_3arcsec_4097.tif")
    results = []
    with tempfile.TemporaryDirectory(prefix="ig_big_") as tmp:
        cases = {"sierra_4097": (sierra, (36.7, -118.3))}
        imagery = None
        if "sierra_4097_ortho" in args.cases.split(","):
            imagery = os.path.join(tmp, "sierra_ortho_x%d.tif" % args.imagery_scale)
            t0 = time.monotonic()
            subprocess.run([os.path.join(args.build, "bin", "imagery_tool"), "make", sierra, imagery,
                            str(args.imagery_scale), "0", "compress"], check=True)
            print("made %s (%.0f MB) in %.0f s" % (imagery, os.path.getsize(imagery) / 1e6, time.monotonic() - t0),
                  flush=True)
            cases["sierra_4097_ortho"] = (sierra, (36.7, -118.3))
        for n in (5, 8):
            if "sierra_%dx%d_%d" % (n, n, 4096 * n + 1) not in args.cases.split(","):
                continue
            vrt = os.path.join(tmp, "sierra_%dx%d.vrt" % (n, n))
            subprocess.run([sys.executable, os.path.join(HERE, "make_copies_vrt.py"), ig, sierra, str(n), vrt],
                           check=True)
            cases["sierra_%dx%d_%d" % (n, n, 4096 * n + 1)] = (vrt, (36.0, -117.0))  # a corner of four copies
        if "synthetic_tiles_32769" in args.cases:
            # The synthetic fractal refined to 32769^2 as 8 x 8 GeoTIFF tiles
            # (a folder: mosaicked in memory); flown across the corner of four tiles.
            folder = os.path.join(tmp, "synthetic_tiles")
            t0 = time.monotonic()
            made = subprocess.run([os.path.join(args.build, "bin", "make_synthetic_tiles"), folder],
                                  check=True, capture_output=True, text=True)
            info = json.loads(made.stdout)
            print("made %d tiles of the synthetic %dx%d in %.0f s" % (info["tiles"], info["width"], info["height"],
                                                                     time.monotonic() - t0), flush=True)
            cases["synthetic_tiles_32769"] = (folder, ("local", *info["centre_local_m"]))
        for name in args.cases.split(","):
            dem, centre = cases[name]
            r = run_case(ig, name, dem, centre, tmp, args, imagery if name.endswith("_ortho") else None)
            print(json.dumps(r), flush=True)
            results.append(r)
    with open(args.out, "w") as f:
        f.write("| case | samples | load (s) | start to first frame (s) | peak RSS (MB) | RSS bytes / sample | "
                "frames | frame median / p99 (ms) | LOD / terrain p99 (ms) | uploads (MB per s of flight, max KB per frame) | "
                "heights | page-ins per s (tiles) | frames waiting on I/O | imagery |\n")
        f.write("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
        for r in results:
            if "error" in r:
                f.write("| %s | refused: %s |\n" % (r["name"], r["error"]))
                continue
            pg = r["paging"]
            im = (pg or {}).get("imagery")
            if im:
                imagery_cell = ("%dx%d paged, %.0f MB budget, cache peak %.0f MB, %.1f page-ins/s, %d held moves "
                                "(%d frames), %d frames waited, %d failed tiles" % (
                                    im["full_size"][0], im["full_size"][1], im["budget_mb"], im["peak_resident_mb"],
                                    im["page_ins_per_s"], im["held_moves"], im["frames_held"],
                                    im["frames_waited_on_io"], im["failed_tiles"]))
            else:
                imagery_cell = "-"
            if pg and "budget_mb" in pg:
                heights = "paged, %.0f MB budget, cache peak %.0f MB" % (pg["budget_mb"], pg["peak_resident_mb"])
                io = "%d (%d tiles waited for); Level1 held in %d frames" % (
                    pg["frames_waited_on_io"], pg["page_waits"], r["level1_held"])
                rate = "%.1f" % pg["page_ins_per_s"]
            else:
                heights, io, rate = "whole", "0 (no I/O after load)", "-"
            f.write("| %s | %s | %.1f | %.1f | %.0f | %.2f | %d | %.0f / %.0f | %.1f / %.0f | %.2f, %.0f | %s | %s | %s | %s |\n" % (
                r["name"], r["size"], r["load_s"], r["first_frame_s"], r["rss_mb"], r["bytes_per_sample"], r["frames"],
                r["median_ms"], r["p99_ms"], r["lod_p99_ms"], r["terrain_p99_ms"], r["upload_mb_s"], r["upload_max_kb"],
                heights, rate, io, imagery_cell))
        f.write("\nCommand: `IG_DEM_DIR=%s %s %s %s --duration %g --step %g --size %dx%d --cases %s%s`\n" % (
            dem_dir, os.path.relpath(__file__), args.build, args.out, args.duration, args.step, *args.size, args.cases,
            (" --budget-mb %d" % args.budget_mb if args.budget_mb else "") +
            (" --imagery-scale %d" % args.imagery_scale if "sierra_4097_ortho" in args.cases else "") +
            (" --imagery-budget-mb %d" % args.imagery_budget_mb if args.imagery_budget_mb else "")))
    print("wrote", args.out)


if __name__ == "__main__":
    main()
