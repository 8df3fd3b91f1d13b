#!/usr/bin/env python3
"""Matched-error ratios at every two-level setting of an `ig bench --sweep`
run (results.csv), not only at its default: for each two-level row, each
baseline's time at that row's mean horizon error (linear interpolation along
its sweep, as ig bench's matched table; "<=" when every point is more
accurate, ">" when none is as accurate) divided by two-level's time.
  tools/bench/matched_ratios.py OUT/results.csv [--time cpu_ms_median|frame_ms_median]"""
import argparse
import csv
from collections import OrderedDict


def time_at(points, target, key):
    """(kind, time) of one method's sweep at `target` px: exact, interpolated, at most, not reached."""
    best = None
    for p in points:
        if abs(p["horizon_mean_px"] - target) <= 1e-9 * max(1.0, target):
            best = p[key] if best is None else min(best, p[key])
    if best is not None:
        return "", best
    for a, b in zip(points, points[1:]):
        e0, e1 = a["horizon_mean_px"], b["horizon_mean_px"]
        if min(e0, e1) <= target <= max(e0, e1) and e0 != e1:
            t = a[key] + (target - e0) / (e1 - e0) * (b[key] - a[key])
            best = t if best is None else min(best, t)
    if best is not None:
        return "", best
    if all(p["horizon_mean_px"] < target for p in points):
        return "<= ", min(p[key] for p in points)
    return "> ", min(points, key=lambda p: p["horizon_mean_px"])[key]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("results")
    ap.add_argument("--time", default="cpu_ms_median")
    a = ap.parse_args()
    methods = OrderedDict()
    for r in csv.DictReader(open(a.results)):
        r["horizon_mean_px"] = float(r["horizon_mean_px"])
        r[a.time] = float(r[a.time])
        methods.setdefault(r["method"], []).append(r)
    baselines = [m for m in methods if m not in ("twolevel", "reference")]
    print(f"ratio = baseline {a.time} / two-level {a.time} at two-level's horizon error (>1: two-level is faster)\n")
    print("| two-level setting | horizon px | " + a.time + " | " + " | ".join(baselines) + " |")
    print("|---|---|---|" + "---|" * len(baselines))
    for t in methods.get("twolevel", []):
        cells = []
        for m in baselines:
            kind, v = time_at(methods[m], t["horizon_mean_px"], a.time)
            cells.append(f"{kind}{v / t[a.time]:.2f}")
        print(f"| {t['knob_name']}={t['knob_value']} | {t['horizon_mean_px']:.2f} | {t[a.time]:.1f} | " +
              " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
