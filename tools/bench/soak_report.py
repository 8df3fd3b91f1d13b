#!/usr/bin/env python3
"""The soak benchmark's sampler and report (tools/bench/soak.sh).

  soak_report.py sample PID OUT.csv [--every S]
      Every S seconds (default 10) until PID is gone: VmRSS, RssAnon, RssFile
      and Threads from /proc/PID/status and the number of entries in
      /proc/PID/fd, one CSV row each (t_s since the sampler started,
      steady_s on the monotonic clock, the clock of frames.csv's
      frame_complete_s).

  soak_report.py report RUN_DIR [--warmup S] [--table-every S]
                 [--check-flat-mb MB --check-for S]
      Markdown to stdout from RUN_DIR (soak.sh's run.json, samples.csv,
      serve/frames.csv, serve/summary.json, host.log, mbpoll.log): the
      samples (time, RSS MB, files, threads; every --table-every seconds,
      default every sample), growth after the warm-up (the last sample of
      the flight against the first after its first --warmup seconds,
      default 60), frame-time percentiles, and the frames over twice the
      frame budget (and over twice the run's median), those with page
      waits, page-ins or uploads beyond the run's median (the IG's own
      doing) apart from the rest, each with its largest stage. With
      --check-flat-mb: checks and
      prints PASS / FAIL lines (ig serve exit status 0, summary.json
      written, over the --check-for seconds after the warm-up resident
      memory grown by at most MB (the median of the stretch's last third
      against that of its first: a leak keeps what it takes, while the heap
      handing back and taking again a few MB for a second is no growth) and
      open files and threads constant).

  soak_report.py replay RUN_DIR OUT.json [--first F] [--last F] [--every N]
      An `ig run` scenario that flies again, offline, frames F..L of the
      soak (every Nth frame's rendered pose from serve/frames.csv as a path
      key, terrain-local, at the soak's image size and the scenario's
      field of view and terrain): a stretch of the hour (its largest
      frames, say) to profile or trace in a minute.
"""
import argparse
import csv
import json
import math
import os
import re
import statistics
import sys
import time


def read_proc(pid):
    status = {}
    with open("/proc/%d/status" % pid) as f:
        for line in f:
            k, _, v = line.partition(":")
            status[k] = v.strip()
    if status.get("State", "").startswith("Z") or "VmRSS" not in status:
        return None  # exited, not yet reaped
    kb = lambda k: int(status.get(k, "0 kB").split()[0])
    return {"rss_kb": kb("VmRSS"), "rss_anon_kb": kb("RssAnon"), "rss_file_kb": kb("RssFile"),
            "fds": len(os.listdir("/proc/%d/fd" % pid)), "threads": int(status["Threads"])}


def sample(args):
    start = time.monotonic()
    fields = ["t_s", "steady_s", "rss_kb", "rss_anon_kb", "rss_file_kb", "fds", "threads"]
    with open(args.out, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(fields)
        f.flush()
        k = 0
        while True:
            now = time.monotonic()
            try:
                s = read_proc(args.pid)
            except (FileNotFoundError, ProcessLookupError):
                s = None
            if s is None:
                return 0
            w.writerow(["%.3f" % (now - start), "%.4f" % now] + [s[k2] for k2 in fields[2:]])
            f.flush()
            k += 1
            # On the period from the start, not after each read: no drift.
            time.sleep(max(0.0, start + k * args.every - time.monotonic()))


def pct(values, q):
    # Nearest rank, as the IG's own summary (stats/frame_log.cpp).
    v = sorted(values)
    if not v:
        return float("nan")
    return v[min(len(v), max(1, math.ceil(q * len(v)))) - 1]


def slope_per_hour(ts, ys):
    n = len(ts)
    if n < 2:
        return 0.0
    mt, my = sum(ts) / n, sum(ys) / n
    den = sum((t - mt) ** 2 for t in ts)
    return 3600.0 * sum((t - mt) * (y - my) for t, y in zip(ts, ys)) / den if den else 0.0


def num(row, key, default=0.0):
    v = row.get(key)
    try:
        return float(v) if v not in (None, "") else default
    except ValueError:
        return default


def mbpoll_stats(path):
    """Polls, frame counter first/last (registers 2-3, u32 high word first), statistics line."""
    if not os.path.exists(path):
        return None
    polls, counters, regs, stats = 0, [], {}, ""
    with open(path, errors="replace") as f:
        for line in f:
            if line.startswith("-- Polling"):
                if 2 in regs and 3 in regs:
                    counters.append(regs[2] * 65536 + regs[3])
                polls, regs = polls + 1, {}
            elif line.startswith("[") and "]:" in line:
                a, _, v = line.partition("]:")
                try:
                    regs[int(a[1:])] = int(v.split()[0])
                except ValueError:
                    pass
            elif "frames transmitted" in line:
                stats = line.strip()
    if 2 in regs and 3 in regs:
        counters.append(regs[2] * 65536 + regs[3])
    decreasing = sum(1 for a, b in zip(counters, counters[1:]) if b < a)
    return {"polls": polls, "first": counters[0] if counters else None, "last": counters[-1] if counters else None,
            "decreasing": decreasing, "stats": stats}


def report(args):
    d = args.run_dir
    run = json.load(open(os.path.join(d, "run.json")))
    samples = list(csv.DictReader(open(os.path.join(d, "samples.csv"))))
    summary_path = os.path.join(d, "serve", "summary.json")
    summary = json.load(open(summary_path)) if os.path.exists(summary_path) else None
    frames_path = os.path.join(d, "serve", "frames.csv")
    rows = list(csv.DictReader(open(frames_path))) if os.path.exists(frames_path) else []
    out = []
    p = out.append

    p("## Soak run: %s, %s s, %s, %s HAT/HOT + %s LOS a host datagram at %s Hz, Modbus %s Hz" % (
        run["terrain"], run["duration_s"], run["size"], run["hot"], run["los"], run["rate_hz"], run["modbus_hz"]))
    p("")
    p("Commit %s; load average (1, 5, 15 min) %s at the start, %s at the end; ig serve exit status %s, host %s." % (
        run["commit"], run["loadavg_start"], run.get("loadavg_end", "?"), run.get("serve_rc", "?"),
        run.get("host_rc", "?")))
    p("")

    # The flight: from the host's first datagram to its last (host.log, steady clock).
    host_lines = open(os.path.join(d, "host.log")).read() if os.path.exists(os.path.join(d, "host.log")) else ""
    m0 = re.search(r"sending for .* from steady_s ([0-9.]+)", host_lines)
    m1 = re.search(r"the last sent at steady_s ([0-9.]+)", host_lines)
    flight_end = float(m1.group(1)) if m1 else float("inf")
    warm = (float(m0.group(1)) if m0 else float(samples[0]["steady_s"])) + args.warmup  # steady clock

    # Samples.
    ts = [float(s["t_s"]) for s in samples]
    rss = [int(s["rss_kb"]) / 1024.0 for s in samples]
    in_flight = [float(s["steady_s"]) <= flight_end for s in samples]
    if m0 and samples:
        p("t = 0 is the first sample, as ig serve started; the host's first datagram went at %.1f s, its last at "
          "%.1f s (samples after that: ig serve stopping, writing its outputs); the warm-up ended at %.1f s." % (
              float(m0.group(1)) - float(samples[0]["steady_s"]), flight_end - float(samples[0]["steady_s"]),
              warm - float(samples[0]["steady_s"])))
        p("")
    p("| time (s) | RSS (MB) | anon / file (MB) | open files | threads |")
    p("|---:|---:|---:|---:|---:|")
    # Sample k was taken at k periods (the sampler keeps to its period); every step-th is shown.
    step = max(1, round(args.table_every / float(run["sample_every_s"])))
    for k, s in enumerate(samples):
        t = float(s["t_s"])
        if k % step == 0 or k == len(samples) - 1 or not in_flight[k]:
            p("| %.0f%s | %.1f | %.1f / %.1f | %s | %s |" % (
                t, "" if in_flight[k] else " (stopping)", int(s["rss_kb"]) / 1024.0, int(s["rss_anon_kb"]) / 1024.0,
                int(s["rss_file_kb"]) / 1024.0, s["fds"], s["threads"]))
    p("")
    steady = [float(s["steady_s"]) for s in samples]
    after = [k for k in range(len(samples)) if steady[k] >= warm and in_flight[k]]
    if len(after) >= 2:
        a, b = after[0], after[-1]
        grow = rss[b] - rss[a]
        seg_t, seg_rss = [ts[k] for k in after], [rss[k] for k in after]
        p("After the flight's %g-s warm-up, to its end (%d samples, %.0f s to %.0f s): RSS %.1f -> %.1f MB, growth %+.1f MB (%+.2f %%); "
          "min %.1f, max %.1f MB; least-squares slope %+.1f MB/h. Open files %s, threads %s." % (
              args.warmup, len(after), ts[a], ts[b], rss[a], rss[b], grow, 100.0 * grow / rss[a], min(seg_rss),
              max(seg_rss), slope_per_hour(seg_t, seg_rss),
              "constant (%s)" % samples[a]["fds"] if len({samples[k]["fds"] for k in after}) == 1 else
              "%s..%s" % (min(int(samples[k]["fds"]) for k in after), max(int(samples[k]["fds"]) for k in after)),
              "constant (%s)" % samples[a]["threads"] if len({samples[k]["threads"] for k in after}) == 1 else
              "%s..%s" % (min(int(samples[k]["threads"]) for k in after),
                          max(int(samples[k]["threads"]) for k in after))))
        p("")

    # Frames.
    if rows:
        budget = summary["frame_time"]["budget_ms"] if summary else 16.667
        wall = [num(r, "wall_ms") for r in rows]
        done = [num(r, "frame_complete_s") for r in rows]
        gaps = [b - a for a, b in zip(done, done[1:])]
        p("Frames: %d in %.0f s (%.1f a second). wall_ms (the frame's work: pose, LOD, passes, readback): "
          "p50 %.1f, p95 %.1f, p99 %.1f, max %.1f ms. Frame to frame (frame_complete_s): p50 %.1f, p95 %.1f, "
          "p99 %.1f, max %.1f ms." % (
              len(rows), done[-1] - done[0], (len(rows) - 1) / max(done[-1] - done[0], 1e-9), pct(wall, .5),
              pct(wall, .95), pct(wall, .99), max(wall), 1e3 * pct(gaps, .5), 1e3 * pct(gaps, .95),
              1e3 * pct(gaps, .99), 1e3 * max(gaps) if gaps else 0))
        p("")
        uploads = sorted(num(r, "upload_bytes") for r in rows)
        median_upload = uploads[len(uploads) // 2]
        paged = "page_waits" in rows[0]
        stages = [("terrain_ms", "terrain passes"), ("lod_ms", "LOD"), ("sky_ms", "sky"), ("resolve_ms", "resolve"),
                  ("readback_ms", "readback (final.png)"), ("pose_ms", "pose")]

        def largest(r):
            parts = {name: num(r, key) for key, name in stages}
            parts["outside the stages (descheduled, or GL work not in a stage)"] = num(r, "wall_ms") - sum(parts.values())
            return max(parts, key=parts.get)

        def split(threshold, what):
            # The IG's own doing: the first frame (first fills), a frame that
            # waited for a tile, that uploaded more than the run's median (the
            # height window scrolling, a new Level1 size's walls), or during
            # which the background thread paged tiles in (its reads and decoding
            # share the two cores); the rest by the frame's largest stage.
            over = [r for r in rows if num(r, "wall_ms") > threshold]
            own, rest = {}, {}
            for r in over:
                why = []
                if r["frame"] == "0":
                    why.append("first frame (first fills)")
                if paged and num(r, "page_waits") > 0:
                    why.append("page waits")
                if paged and num(r, "page_ins") > 0:
                    why.append("tiles paged in during it")
                if num(r, "upload_bytes") > median_upload:
                    why.append("uploads beyond the median")
                if why:
                    k = " + ".join(why) + "; largest stage: " + largest(r)
                    own[k] = own.get(k, 0) + 1
                else:
                    k = largest(r)
                    rest[k] = rest.get(k, 0) + 1
            p("Frames over %s (wall_ms > %.1f ms): **%d of %d** (%.2f %%); with page waits, page-ins or uploads beyond "
              "the run's median (%.0f bytes), the IG's own doing: %d; the rest: %d." % (
                  what, threshold, len(over), len(rows), 100.0 * len(over) / len(rows), median_upload,
                  sum(own.values()), sum(rest.values())))
            p("")
            if over:
                p("| kind | why | frames |")
                p("|---|---|---:|")
                for k, v in sorted(own.items(), key=lambda kv: -kv[1]):
                    p("| IG's own | %s | %d |" % (k, v))
                for k, v in sorted(rest.items(), key=lambda kv: -kv[1]):
                    p("| the rest | largest stage: %s | %d |" % (k, v))
                p("")

        split(2 * budget, "twice the frame budget")
        # On a CPU rasterizer most frames may be over that: the spikes, against the run's own typical frame.
        split(2 * pct(wall, .5), "twice the run's median frame")
        mean_stage = {name: sum(num(r, key) for r in rows) / len(rows) for key, name in stages}
        p("Mean stage times over all frames: " + ", ".join("%s %.2f ms" % (k, v) for k, v in mean_stage.items()) + ".")
        p("")
    if summary:
        hs = summary.get("host_services", {})
        p("Host services (summary.json): %s requests, %s answered, %s deferred, dropped %s; answer time a frame mean "
          "%.3f ms, max %.2f ms." % (hs.get("requests"), hs.get("answered"), hs.get("deferred"),
                                     json.dumps(hs.get("dropped")), hs.get("answer_ms_mean", 0), hs.get("answer_ms_max", 0)))
        pg = summary.get("paging")
        if pg:
            p("")
            p("Paging (summary.json): budget %s MB, cache peak %s MB, at the end %s MB, %s evictions, %.2f page-ins a "
              "second (%s tiles), frames that waited on I/O %s (%s tiles), tiles waited for in all (frames and host "
              "queries) %s, deferred reads %s." % (
                  pg.get("budget_mb"), pg.get("peak_resident_mb"), pg.get("resident_mb"), pg.get("evictions"),
                  pg.get("page_ins_per_s", 0), pg.get("page_ins"), pg.get("frames_waited_on_io"), pg.get("page_waits"),
                  pg.get("page_waits_total"), pg.get("deferred_reads")))
            if rows and "page_ins" in rows[0]:
                t0 = num(rows[0], "frame_complete_s")
                per = {}
                for r in rows:
                    m = int((num(r, "frame_complete_s") - t0) // 60)
                    per[m] = per.get(m, 0) + int(num(r, "page_ins"))
                p("")
                p("Tiles paged in during frames, per minute from the first frame: " +
                  " ".join(str(per.get(m, 0)) for m in range(max(per) + 1)) + ".")
        p("")
        p("Frames outside the terrain %s, below it %s; Modbus (summary.json): %s." % (
            summary.get("frames_outside_terrain"), summary.get("frames_below_terrain"), json.dumps(summary.get("modbus"))))
        pm = summary.get("process_memory")
        if pm:
            p("")
            p("At the end (summary.json process_memory): resident %.1f MB (peak %.1f MB); the C library's heap %.1f MB "
              "in use, %.1f MB free and kept for reuse, %.1f MB of it mapped blocks." % (
                  pm.get("rss_mb", 0), pm.get("peak_rss_mb", 0), pm.get("heap_in_use_mb", 0),
                  pm.get("heap_free_mb", 0), pm.get("heap_mmapped_mb", 0)))
        p("")
    mb = mbpoll_stats(os.path.join(d, "mbpoll.log"))
    if mb:
        p("mbpoll: %d polls of the 37 status registers; frame counter %s -> %s, decreasing %d times; %s" % (
            mb["polls"], mb["first"], mb["last"], mb["decreasing"], mb["stats"] or "(no statistics line)"))
        p("")
    for line in host_lines.splitlines():
        if line.startswith("soak host:"):
            p("    " + line.rstrip())
    p("")
    p("Commands:")
    p("")
    p("    " + run["serve_command"])
    p("    " + run["host_command"])
    print("\n".join(out))

    if args.check_flat_mb is None:
        return 0
    failures = []
    if run.get("serve_rc") != 0:
        failures.append("ig serve exit status %s" % run.get("serve_rc"))
    if run.get("host_rc") != 0:
        failures.append("host exit status %s" % run.get("host_rc"))
    if summary is None:
        failures.append("no summary.json")
    # From the first sample after the warm-up to the first at least --check-for later, all in the flight.
    first = next((k for k in range(len(samples)) if steady[k] >= warm), None)
    last = next((k for k in range(len(samples)) if first is not None and steady[k] >= steady[first] + args.check_for),
                None)
    stretch = list(range(first, last + 1)) if first is not None and last is not None and in_flight[last] else []
    if not stretch:
        failures.append("the samples do not cover %g s after the warm-up (run too short)" % args.check_for)
    else:
        seg = [rss[k] for k in stretch]
        spread = max(seg) - min(seg)
        third = max(1, len(seg) // 3)
        growth = statistics.median(seg[-third:]) - statistics.median(seg[:third])
        fds = sorted({int(samples[k]["fds"]) for k in stretch})
        threads = sorted({int(samples[k]["threads"]) for k in stretch})
        print("check: %d samples from %.1f s to %.1f s: RSS %.2f..%.2f MB (spread %.2f MB), median of the last "
              "third against the first %+.2f MB (limit %g), open files %s, threads %s" % (
                  len(stretch), ts[stretch[0]], ts[stretch[-1]], min(seg), max(seg), spread, growth,
                  args.check_flat_mb, fds, threads))
        if growth > args.check_flat_mb:
            failures.append("resident memory grew %.2f MB (limit %g MB)" % (growth, args.check_flat_mb))
        if len(fds) != 1:
            failures.append("open files changed: %s" % fds)
        if len(threads) != 1:
            failures.append("threads changed: %s" % threads)
    if summary is not None and summary.get("frames_rendered", 0) < 1:
        failures.append("no frames rendered")
    for f in failures:
        print("FAIL soak: " + f)
    if not failures:
        print("PASS soak: no crash, resident memory grew no more than %g MB, open files and threads constant" %
              args.check_flat_mb)
    return 1 if failures else 0


def replay(args):
    with open(os.path.join(args.run_dir, "run.json")) as f:
        run = json.load(f)
    with open(os.path.join(args.run_dir, "scenario.json")) as f:
        scenario = json.load(f)
    keys, t0 = [], None
    with open(os.path.join(args.run_dir, "serve", "frames.csv")) as f:
        for row in csv.DictReader(f):
            frame = int(row["frame"])
            if frame < args.first or (args.last is not None and frame > args.last) or (frame - args.first) % args.every:
                continue
            t = float(row["sim_time_s"])
            t0 = t if t0 is None else t0
            keys.append({"t": round(t - t0, 3),
                         "position": [float(row["x_m"]), float(row["y_m"]), float(row["z_m"])],
                         "hpr": [float(row["heading_deg"]), float(row["pitch_deg"]), float(row["roll_deg"])]})
    if len(keys) < 2 or keys[-1]["t"] <= 0:
        print("soak_report.py replay: fewer than two frames from %d to %s in %s" % (
            args.first, args.last, args.run_dir), file=sys.stderr)
        return 1
    width, height = (int(v) for v in run["size"].split("x"))
    out = {"name": scenario.get("name", "soak") + "_replay", "terrain": scenario["terrain"],
           "render": dict(scenario.get("render", {}), width=width, height=height),
           "time": {"step_s": args.step, "duration_s": keys[-1]["t"]},
           "path": {"frame": "local", "keys": keys}}
    with open(args.out, "w") as f:
        json.dump(out, f, indent=1)
    print("soak_report.py replay: %d keys over %.1f s (frames %d to %s) -> %s" % (
        len(keys), keys[-1]["t"], args.first, args.last, args.out))
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    s = sub.add_parser("sample")
    s.add_argument("pid", type=int)
    s.add_argument("out")
    s.add_argument("--every", type=float, default=10.0)
    r = sub.add_parser("report")
    r.add_argument("run_dir")
    r.add_argument("--warmup", type=float, default=60.0)
    r.add_argument("--table-every", type=float, default=0.0)
    r.add_argument("--check-flat-mb", type=float)
    r.add_argument("--check-for", type=float, default=30.0)
    p = sub.add_parser("replay")
    p.add_argument("run_dir")
    p.add_argument("out")
    p.add_argument("--first", type=int, default=0)
    p.add_argument("--last", type=int)
    p.add_argument("--every", type=int, default=60)
    p.add_argument("--step", type=float, default=0.25, help="the replay's time step, seconds")
    args = ap.parse_args()
    return {"sample": sample, "report": report, "replay": replay}[args.cmd](args)


if __name__ == "__main__":
    sys.exit(main())
