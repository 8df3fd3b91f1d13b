#!/usr/bin/env python3
"""Scenario variants and summary checks for the sun tests (tests/cli/sun.cmake).

  sun_check.py make IN OUT [--time ISO] [--no-origin]
      OUT = IN with environment.time_utc set (and render.sun_direction
      dropped), or with terrain.generator.origin removed.
  sun_check.py check SUMMARY --elevation DEG [--azimuth DEG] --tolerance DEG
      Exits 1 unless summary.json's sun_elevation_deg (and sun_azimuth_deg)
      are within the tolerance.
"""
import argparse
import json
import sys


def make(args):
    with open(args.input) as f:
        doc = json.load(f)
    if args.time:
        doc.setdefault("render", {}).pop("sun_direction", None)
        doc["environment"] = {"time_utc": args.time}
    if args.no_origin:
        doc["terrain"]["generator"].pop("origin", None)
    with open(args.output, "w") as f:
        json.dump(doc, f, indent=1)


def check(args):
    with open(args.summary) as f:
        s = json.load(f)
    el, az = s["sun_elevation_deg"], s["sun_azimuth_deg"]
    ok = abs(el - args.elevation) <= args.tolerance
    if args.azimuth is not None:
        ok = ok and abs((az - args.azimuth + 180.0) % 360.0 - 180.0) <= args.tolerance
    print(f"sun elevation {el:.4f} deg, azimuth {az:.4f} deg: {'sun ok' if ok else 'MISMATCH'}")
    return 0 if ok else 1


def main():
    p = argparse.ArgumentParser()
    sub = p.add_subparsers(dest="cmd", required=True)
    m = sub.add_parser("make")
    m.add_argument("input")
    m.add_argument("output")
    m.add_argument("--time")
    m.add_argument("--no-origin", action="store_true")
    c = sub.add_parser("check")
    c.add_argument("summary")
    c.add_argument("--elevation", type=float, required=True)
    c.add_argument("--azimuth", type=float)
    c.add_argument("--tolerance", type=float, required=True)
    args = p.parse_args()
    if args.cmd == "make":
        make(args)
        return 0
    return check(args)


if __name__ == "__main__":
    sys.exit(main())
