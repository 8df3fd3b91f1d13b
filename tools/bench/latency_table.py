#!/usr/bin/env python3
"""Transport delay and pose error per run of tools/bench/latency.sh.

For every frame that showed a received pose (ig serve's frames.csv):
  transport delay = frame complete - receive time of the newest pose used
                    (frames.csv transport_delay_ms; the renderer ends with glFinish)
  motion lag      = frame complete - the host instant the pose shows (both on the
                    steady clock the sender and the IG share on one machine)
  error           = |shown position - where the host was at frame complete|
                    (ig send's log: the path against the sender's steady clock)
Prints one Markdown row per run: median and p99 of each."""
import bisect
import csv
import json
import math
import os
import statistics
import sys


def pct(v, q):
    v = sorted(v)
    return v[min(len(v) - 1, int(q * len(v)))]


def host_position(log, t):
    """The sender's path at steady time t, linear between its logged poses."""
    times = log["steady"]
    k = bisect.bisect_right(times, t)
    if k == 0 or k >= len(times):
        return None
    a, b = k - 1, k
    s = (t - times[a]) / (times[b] - times[a])
    return [log["pos"][a][i] + s * (log["pos"][b][i] - log["pos"][a][i]) for i in range(3)]


def main():
    out, runs = sys.argv[1], sys.argv[2:]
    print("| mode | host rate | stream | frames | transport delay median / p99 (ms) | motion lag median / p99 (ms) "
          "| error median / p99 (m) | playout delay (ms) | frame interval (ms) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name in runs:
        mode, rate, stream = name.split("_")
        log = {"steady": [], "pos": []}
        last_sent = 0.0
        with open(os.path.join(out, name + ".send.csv")) as f:
            for r in csv.DictReader(f):
                log["steady"].append(float(r["steady_s"]))
                log["pos"].append([float(r["x_m"]), float(r["y_m"]), float(r["z_m"])])
                if r["sent"] == "1":
                    last_sent = float(r["steady_s"])
        with open(os.path.join(out, name, "summary.json")) as f:
            playout = json.load(f)["pose_intake"]["filter"]["playout_delay_ms"]
        with open(os.path.join(out, name, "frames.csv")) as f:
            rows = [r for r in csv.DictReader(f) if r["pose_source"] != "none" and float(r["shown_time_s"]) > 0]
        rows = rows[30:]  # the filter's start-up (first packets, delay settling)
        delay, lag, err, interval = [], [], [], []
        prev = None
        for r in rows:
            done = float(r["frame_complete_s"])
            truth = host_position(log, done)
            if truth is None or done > last_sent:  # the host has stopped: not part of the measurement
                continue
            delay.append(float(r["transport_delay_ms"]))
            lag.append((done - float(r["shown_time_s"])) * 1e3)
            err.append(math.dist(truth, [float(r["x_m"]), float(r["y_m"]), float(r["z_m"])]))
            if prev is not None:
                interval.append((done - prev) * 1e3)
            prev = done
        if not delay:
            print(f"| {mode} | {rate} | {stream} | 0 | - | - | - | - | - |")
            continue
        print(f"| {mode} | {rate} | {stream} | {len(delay)} | {statistics.median(delay):.1f} / {pct(delay, 0.99):.1f} "
              f"| {statistics.median(lag):.1f} / {pct(lag, 0.99):.1f} | {statistics.median(err):.2f} / "
              f"{pct(err, 0.99):.2f} | {playout if mode == 'smooth' else 0:.1f} | {statistics.median(interval):.1f} |")


if __name__ == "__main__":
    main()
