#!/usr/bin/env python3
"""Checks that the poses an IG logged (frames.csv of ig serve / ig run
--recording) follow the path a sender sent (ig send --log): every logged
pose taken from received packets lies within a tolerance of the sent
polyline, its heading/pitch/roll match the nearest sent sample, and enough
frames used received poses. Prints the measured maxima; exit 1 on failure."""
import argparse
import csv
import math
import sys


def angle_diff(a, b):
    d = (a - b) % 360.0
    return min(d, 360.0 - d)


def seg_distance(p, a, b):
    ab = [b[i] - a[i] for i in range(3)]
    ap = [p[i] - a[i] for i in range(3)]
    den = sum(c * c for c in ab)
    t = 0.0 if den == 0 else max(0.0, min(1.0, sum(ap[i] * ab[i] for i in range(3)) / den))
    q = [a[i] + t * ab[i] for i in range(3)]
    return math.dist(p, q), t


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("frames_csv")
    ap.add_argument("send_log")
    ap.add_argument("--pos-tol", type=float, default=1.0)
    ap.add_argument("--angle-tol", type=float, default=0.5)
    ap.add_argument("--min-frames", type=int, default=20)
    ap.add_argument("--extrapolation-tol", type=float, default=70.0,
                    help="frames the filter extrapolated or held (after the stream ends, in gaps): "
                         "max distance from the path, about 0.2 s x speed")
    ap.add_argument("--expect-bad", type=int, default=None, help="packets_bad must be at least this")
    ap.add_argument("--min-total-frames", type=int, default=0, help="frames rendered in all (the IG kept going)")
    ap.add_argument("--hold-tol", type=float, default=None,
                    help="the last frame lies within this of the last packet sent (metres): the pose holds "
                         "near it after the host stops")
    ap.add_argument("--sync-frames", action="store_true",
                    help="CIGI synchronous: exactly one frame per host frame sent, in order (host_frame column)")
    ap.add_argument("--max-speed-ratio", type=float, default=None,
                    help="apparent speed between consecutive frames at most this times the fastest sent speed")
    a = ap.parse_args()

    sent = []
    sent_count = 0
    last_sent = None
    times = []
    with open(a.send_log) as f:
        for r in csv.DictReader(f):
            sent.append(([float(r["x_m"]), float(r["y_m"]), float(r["z_m"])],
                         [float(r["heading_deg"]), float(r["pitch_deg"]), float(r["roll_deg"])]))
            times.append(float(r["t_s"]))
            if r["sent"] == "1":
                last_sent = sent[-1][0]
                sent_count += 1
    with open(a.frames_csv) as f:
        all_rows = list(csv.DictReader(f))
    rows = [r for r in all_rows if r["pose_source"] != "none"]
    if len(all_rows) < a.min_total_frames:
        print(f"FAIL: only {len(all_rows)} frames rendered (need {a.min_total_frames})")
        return 1
    if len(rows) < max(a.min_frames, 1):
        print(f"FAIL: only {len(rows)} frames used received poses (need {a.min_frames})")
        return 1
    worst_pos = worst_ang = worst_extra = 0.0
    interpolated = 0
    for r in rows:
        p = [float(r["x_m"]), float(r["y_m"]), float(r["z_m"])]
        best = (1e30, 0, 0.0)
        for k in range(len(sent) - 1):
            d, t = seg_distance(p, sent[k][0], sent[k + 1][0])
            if d < best[0]:
                best = (d, k, t)
        d, k, t = best
        ref = sent[k + 1][1] if t > 0.5 else sent[k][1]
        got = [float(r["heading_deg"]), float(r["pitch_deg"]), float(r["roll_deg"])]
        ang = max(angle_diff(got[i], ref[i]) for i in range(3))
        # Between two samples the attitude may sit anywhere between them.
        ang = min(ang, max(angle_diff(got[i], sent[k][1][i]) for i in range(3)))
        if r["pose_mode"] == "interpolating":
            interpolated += 1
            worst_pos, worst_ang = max(worst_pos, d), max(worst_ang, ang)
        else:
            worst_extra = max(worst_extra, d)
        if not all(math.isfinite(v) for v in p + got):
            print(f"FAIL: non-finite pose at frame {r['frame']}")
            return 1
    ok_extra = True
    if a.sync_frames:
        host_frames = [int(r["host_frame"]) for r in all_rows]
        in_order = host_frames == list(range(len(host_frames)))
        print(f"synchronous: {len(all_rows)} frames for {sent_count} host frames sent; host frames in order, each "
              f"once: {in_order}")
        ok_extra = ok_extra and in_order and len(all_rows) == sent_count
    if a.hold_tol is not None:
        d_last = math.dist([float(rows[-1][k]) for k in ("x_m", "y_m", "z_m")], last_sent)
        print(f"last frame ({rows[-1]['pose_mode']}): {d_last:.1f} m from the last packet sent (limit {a.hold_tol} m)")
        ok_extra = ok_extra and d_last <= a.hold_tol
    if a.max_speed_ratio is not None:
        true_max = max(math.dist(sent[k][0], sent[k + 1][0]) / (times[k + 1] - times[k])
                       for k in range(len(sent) - 1) if times[k + 1] > times[k])
        fastest = 0.0
        for r0, r1 in zip(rows, rows[1:]):
            dt = float(r1["sim_time_s"]) - float(r0["sim_time_s"])
            p0 = [float(r0[k]) for k in ("x_m", "y_m", "z_m")]
            p1 = [float(r1[k]) for k in ("x_m", "y_m", "z_m")]
            if dt > 0:
                fastest = max(fastest, math.dist(p0, p1) / dt)
        print(f"apparent speed between frames max {fastest:.1f} m/s, sent path max {true_max:.1f} m/s: "
              f"ratio {fastest / true_max:.2f} (limit {a.max_speed_ratio})")
        ok_extra = ok_extra and fastest <= a.max_speed_ratio * true_max
    bad = int(rows[-1]["packets_bad"])
    print(f"frames with received poses: {len(rows)} ({interpolated} interpolated); interpolated: max distance to "
          f"sent path {worst_pos:.3f} m, max attitude difference {worst_ang:.3f} deg; extrapolated/held: max "
          f"distance {worst_extra:.1f} m; packets ok {rows[-1]['packets_ok']}, bad {bad}")
    ok = worst_pos <= a.pos_tol and worst_ang <= a.angle_tol and worst_extra <= a.extrapolation_tol
    ok = ok and interpolated >= a.min_frames and ok_extra
    if a.expect_bad is not None and bad < a.expect_bad:
        print(f"FAIL: expected at least {a.expect_bad} bad packets, saw {bad}")
        ok = False
    print("follows the sent path" if ok else "FAIL: pose does not follow the sent path")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
