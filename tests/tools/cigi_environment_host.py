#!/usr/bin/env python3
"""An independent CIGI 3.3 host for ig serve's environment packets.

Packs every packet with struct from the ICD's byte layouts (no code shared
with the IG), alternating big- and little-endian datagrams, and drives
`ig serve --latency sync` on the Sierra DEM over loopback:

  frame 0: IG Control, Entity Control (the ownship), a HAT request under it,
           Celestial Sphere Control (2026-06-21 18:30 UTC, clock held),
           Atmosphere Control (visibility 5 000 m), a one-shot Position
           Request for entity 0 and one for entity 5 (unknown), an
           Environmental Conditions Request (weather), a database load
           request and two packets this IG does not act on (Component
           Control, Short Symbol Control);
  frame 1: two collision segments straight down from the ownship, one 50 m
           past the ground (HAT + 50) and one ending 50 m above it, and a
           continuous Position Request for view 0;
  frame 3: Weather Control: cloud layer 1 (stratus, 100 %, base 500 m
           above the ownship, 300 m thick), layer 2 with coverage 150 %
           (refused) and layer 3 of cloud type 12, "other" (refused);
  frame 7: Weather Control disabling layer 1;
  the other frames: Entity Control only.

Checks the answers (Position Response at the pose sent, within 1e-6 deg and
0.5 m; the segment through the ground notified at the HAT distance, the
other never; the weather response's visibility; IG Messages for what is not
supported) and summary.json (visibility_m 5000, the sun within 0.6 deg of
the NOAA solar equations at the ownship, cigi.unsupported by opcode), the
cloud layer drawn from frame 3 to frame 6 (frames.csv passes), the two bad
layers counted under cigi.rejected and named in IG Messages.
The host then stops and the IG is ended by SIGTERM while it waits for the
next host frame: it must exit cleanly and leave final.png.
Prints PASS environment or FAIL lines. Exit 77 without IG_DEM_DIR.

  cigi_environment_host.py IG SRC_DIR OUT_DIR PORT
"""
import json
import math
import os
import signal
import socket
import struct
import subprocess
import sys

LAT, LON, ALT = 36.700, -118.060, 2500.0
HEADING, PITCH, ROLL = 250.0, 0.0, 0.0  # level: the body z axis is the local vertical
FRAMES = 12
failures = []


def fail(msg):
    failures.append(msg)
    print("FAIL " + msg)


# ----------------------------------------------------------- host packets
def ig_control(e, frame):
    # opcode, size, major 3, database 0, mode operate | minor 3 << 4, magic 0x8000
    return struct.pack(e + "BBBbBBHIIII", 1, 24, 3, 0, 1 | (3 << 4), 0, 0x8000, frame, 0, 0, 0)


def ig_control_database(e, frame, database):
    return struct.pack(e + "BBBbBBHIIII", 1, 24, 3, database, 1 | (3 << 4), 0, 0x8000, frame, 0, 0, 0)


def entity_control(e):
    # entity 0, state active, detached; alpha 255; roll, pitch, yaw; lat, lon, alt
    return struct.pack(e + "BBHBBBBHHfffddd", 2, 48, 0, 1, 0, 255, 0, 0, 0, ROLL, PITCH, HEADING, LAT, LON, ALT)


def hat_request(e, rid):
    return struct.pack(e + "BBHBBHddd", 24, 32, rid, 0, 0, 0, LAT, LON, ALT)


def celestial(e, hour, minute, month, day, year, ephemeris):
    flags = (1 if ephemeris else 0) | 0x02 | 0x10  # sun enabled, date valid
    return struct.pack(e + "BBBBBBHIf", 9, 16, hour, minute, flags, 0, 0, month * 1000000 + day * 10000 + year, 0.0)


def atmosphere(e, visibility_m):
    return struct.pack(e + "BBBBffffffI", 10, 32, 1, 50, 15.0, visibility_m, 3.0, 0.0, 270.0, 1013.25, 0)


def weather_control(e, layer, cloud_type, enabled, coverage_pct, base_m, thickness_m):
    # [2] region id, [4] layer, [5] humidity, [6] enable | cloud type << 4,
    # [7] scope 0 (global); f32: air temperature, visibility, scud frequency,
    # coverage, base, thickness, transition band, horizontal and vertical
    # wind, wind direction, pressure, aerosol.
    return struct.pack(e + "BBHBBBBffffffffffff", 12, 56, 0, layer, 80, (1 if enabled else 0) | (cloud_type << 4), 0,
                       10.0, 0.0, 0.0, coverage_pct, base_m, thickness_m, 50.0, 5.0, 0.0, 270.0, 1013.25, 0.0)


def position_request(e, obj, object_class, continuous):
    return struct.pack(e + "BBHBBH", 27, 8, obj, 0, (1 if continuous else 0) | (object_class << 1), 0)


def conditions_request(e, rid):
    return struct.pack(e + "BBBBIddd", 28, 32, 4, rid, 0, LAT, LON, ALT)


def collision_segment(e, seg, z_end):
    # entity 0, segment id, enabled; x1 y1 z1 x2 y2 z2 (body axes, z down); mask
    return struct.pack(e + "BBHBBHffffffII", 22, 40, 0, seg, 1, 0, 0, 0, 0, 0, 0, z_end, 0xFFFFFFFF, 0)


def opaque(op, size):
    return bytes([op, size]) + bytes(size - 2)


# ------------------------------------------------------------ IG packets
def parse_ig(d):
    """Packets of an IG datagram after its Start Of Frame: (last host frame, {opcode: [fields]})."""
    if len(d) < 24 or d[0] != 101 or d[1] != 24:
        return None, {}
    e = ">" if d[6:8] == b"\x80\x00" else "<"
    last_host_frame = struct.unpack_from(e + "I", d, 16)[0]
    out, off = {}, 24
    while off + 2 <= len(d):
        op, size = d[off], d[off + 1]
        if size == 0 or off + size > len(d):
            fail("IG datagram packet runs past its end")
            break
        p = d[off:off + size]
        if op == 108:
            out.setdefault(op, []).append(struct.unpack_from(e + "HBBHdddfff", p, 2))
        elif op == 113:
            out.setdefault(op, []).append(struct.unpack_from(e + "HBBHIf", p, 2))
        elif op == 109:
            out.setdefault(op, []).append(struct.unpack_from(e + "BBffffff", p, 2))
        elif op == 102:
            out.setdefault(op, []).append(struct.unpack_from(e + "HBxxxd", p, 2))
        elif op == 117:
            out.setdefault(op, []).append(p[4:].split(b"\0")[0].decode())
        off += size
    return last_host_frame, out


def start_sync_ig(ig, src, out, port, stop_args):
    """ig serve on the Sierra DEM in CIGI synchronous operation, answering on
    port + 1: (the process, the reply socket, the host's send socket)."""
    os.makedirs(out, exist_ok=True)
    reply = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    reply.bind(("127.0.0.1", port + 1))
    reply.settimeout(30.0)  # a hung IG fails the test instead of hanging it
    log = open(os.path.join(out, "serve.log"), "w")
    serve = subprocess.Popen([ig, "serve", "--config", os.path.join(src, "scenarios/sierra_owens_valley.json"),
                              "--cigi", f"127.0.0.1:{port}", "--cigi-reply", f"127.0.0.1:{port + 1}",
                              "--latency", "sync", *stop_args, "--size", "160x120",
                              "--out", os.path.join(out, "serve"), "--quiet"], stdout=log, stderr=log)
    return serve, reply, socket.socket(socket.AF_INET, socket.SOCK_DGRAM)


# --------------------------------------------------------- NOAA solar position
def noaa_sun(year, month, day, hour, minute, lat, lon):
    """Elevation (with NOAA's refraction) and azimuth, degrees (NOAA's spreadsheet equations)."""
    a = (14 - month) // 12
    y, m = year + 4800 - a, month + 12 * a - 3
    jdn = day + (153 * m + 2) // 5 + 365 * y + y // 4 - y // 100 + y // 400 - 32045
    jd = jdn - 0.5 + (hour + minute / 60.0) / 24.0
    t = (jd - 2451545.0) / 36525.0
    l0 = (280.46646 + t * (36000.76983 + t * 0.0003032)) % 360
    m_ = 357.52911 + t * (35999.05029 - 0.0001537 * t)
    ecc = 0.016708634 - t * (0.000042037 + 0.0000001267 * t)
    r = math.radians
    c = (math.sin(r(m_)) * (1.914602 - t * (0.004817 + 0.000014 * t)) + math.sin(r(2 * m_)) * (0.019993 - 0.000101 * t)
         + math.sin(r(3 * m_)) * 0.000289)
    app = l0 + c - 0.00569 - 0.00478 * math.sin(r(125.04 - 1934.136 * t))
    obl0 = 23 + (26 + (21.448 - t * (46.815 + t * (0.00059 - t * 0.001813))) / 60) / 60
    obl = obl0 + 0.00256 * math.cos(r(125.04 - 1934.136 * t))
    decl = math.degrees(math.asin(math.sin(r(obl)) * math.sin(r(app))))
    yv = math.tan(r(obl / 2)) ** 2
    eot = 4 * math.degrees(yv * math.sin(2 * r(l0)) - 2 * ecc * math.sin(r(m_))
                           + 4 * ecc * yv * math.sin(r(m_)) * math.cos(2 * r(l0))
                           - 0.5 * yv * yv * math.sin(4 * r(l0)) - 1.25 * ecc * ecc * math.sin(2 * r(m_)))
    tst = ((hour * 60 + minute) + eot + 4 * lon) % 1440
    ha = tst / 4 - 180 if tst / 4 >= 0 else tst / 4 + 180
    zen = math.degrees(math.acos(math.sin(r(lat)) * math.sin(r(decl))
                                 + math.cos(r(lat)) * math.cos(r(decl)) * math.cos(r(ha))))
    el = 90 - zen
    refr = 1.02 / math.tan(r(el + 10.3 / (el + 5.11))) / 60 if el > -0.575 else 0.0
    az = math.degrees(math.acos(((math.sin(r(lat)) * math.cos(r(zen))) - math.sin(r(decl)))
                                / (math.cos(r(lat)) * math.sin(r(zen)))))
    az = (az + 180) % 360 if ha > 0 else (540 - az) % 360
    return el + refr, az


def main():
    ig, src, out, port = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
    if not os.environ.get("IG_DEM_DIR"):
        print("IG_DEM_DIR not set: CIGI environment test skipped")
        return 77
    serve, reply, send = start_sync_ig(ig, src, out, port, ["--seconds", "600"])
    answers = []
    try:
        reply.recvfrom(65535)  # the IG's Start Of Frame before the first host frame
        hat = None
        for k in range(FRAMES):
            e = ">" if k % 2 == 0 else "<"
            d = ig_control(e, k) + entity_control(e)
            if k == 0:
                d = (ig_control_database(e, k, 7) + entity_control(e) + hat_request(e, 7)
                     + celestial(e, 18, 30, 6, 21, 2026, False) + atmosphere(e, 5000.0)
                     + position_request(e, 0, 0, False) + position_request(e, 5, 0, False)
                     + conditions_request(e, 3) + opaque(4, 32) + opaque(35, 16))
            elif k == 1:
                d += collision_segment(e, 1, hat + 50.0) + collision_segment(e, 2, hat - 50.0)
                d += position_request(e, 0, 2, True)
            elif k == 3:
                d += (weather_control(e, 1, 10, True, 100.0, ALT + 500.0, 300.0)
                      + weather_control(e, 2, 10, True, 150.0, ALT + 900.0, 300.0)
                      + weather_control(e, 3, 12, True, 50.0, ALT + 900.0, 300.0))
            elif k == 7:
                d += weather_control(e, 1, 10, False, 100.0, ALT + 500.0, 300.0)
            send.sendto(d, ("127.0.0.1", port))
            while True:
                frame, packets = parse_ig(reply.recvfrom(65535)[0])
                if frame == k:
                    break
            answers.append(packets)
            if k == 0:
                hats = packets.get(102, [])
                if not hats or not (hats[0][1] & 1):
                    fail("no valid HAT for the ownship in frame 0")
                    return 1
                hat = hats[0][2]
    except socket.timeout:
        fail("the IG did not answer within 30 s")
        serve.kill()
        return 1
    # The host stops: the IG, waiting for the next host frame, is stopped
    # by a signal and must still leave its last frame as final.png.
    serve.send_signal(signal.SIGTERM)
    if serve.wait() != 0:
        fail("ig serve exited with an error (see serve.log)")
        return 1
    if not os.path.exists(os.path.join(out, "serve", "final.png")):
        fail("no final.png after a synchronous run the host ended")

    # Position Responses: entity 0 at the pose sent; view 0 every frame after frame 1.
    pos0 = [p for p in answers[0].get(108, []) if (p[2] & 7) == 0 and p[0] == 0]
    if len(pos0) != 1:
        fail(f"frame 0: {len(pos0)} Position Responses for entity 0, expected 1")
    else:
        _, _, _, _, lat, lon, alt, roll, pitch, yaw = pos0[0]
        print(f"position response: {lat:.8f} {lon:.8f} {alt:.3f} m, hpr {yaw:.3f} {pitch:.3f} {roll:.3f}")
        if abs(lat - LAT) > 1e-6 or abs(lon - LON) > 1e-6 or abs(alt - ALT) > 0.5:
            fail(f"Position Response {lat} {lon} {alt} is not the pose sent {LAT} {LON} {ALT}")
        if abs((yaw - HEADING + 180) % 360 - 180) > 0.01 or abs(pitch - PITCH) > 0.01:
            fail("Position Response attitude is not the one sent")
    views = [sum(1 for p in a.get(108, []) if (p[2] & 7) == 2) for a in answers]
    if views[1:] != [1] * (FRAMES - 1):
        fail(f"continuous Position Request for view 0: responses per frame {views}")
    # Collision segments: 1 reaches 50 m past the ground, 2 stops 50 m above it.
    hits = [[c for c in a.get(113, [])] for a in answers]
    seg1 = [c for h in hits for c in h if c[1] == 1]
    seg2 = [c for h in hits for c in h if c[1] == 2]
    print(f"HAT {hat:.2f} m; segment 1 notified in {len(seg1)} frames, segment 2 in {len(seg2)}")
    if len(seg1) != FRAMES - 1 or seg2:
        fail("collision segments: the one through the ground must be notified every frame, the other never")
    elif any(abs(c[5] - hat) > 1.0 for c in seg1):
        fail(f"collision distance {seg1[0][5]} is not the HAT {hat}")
    weather = answers[0].get(109, [])
    if len(weather) != 1 or weather[0][0] != 3 or abs(weather[0][3] - 5000.0) > 1e-3:
        fail(f"Weather Conditions Response {weather}: expected request 3 with visibility 5000")
    messages = [m for a in answers for m in a.get(117, [])]
    print("IG messages:", messages)
    for needle in ("opcode 4 ", "opcode 35 ", "database 7", "entity 5", "layer 2: coverage outside 0-100 %",
                   "cloud type 12 (other) is not drawn"):
        if not any(needle in m for m in messages):
            fail(f"no IG Message about {needle.strip()}")

    s = json.load(open(os.path.join(out, "serve", "summary.json")))
    if s.get("visibility_m") != 5000.0:
        fail(f"summary visibility_m {s.get('visibility_m')}, expected 5000")
    el, az = noaa_sun(2026, 6, 21, 18, 30, LAT, LON)
    print(f"sun: ig {s['sun_elevation_deg']:.3f} / {s['sun_azimuth_deg']:.3f} deg, NOAA {el:.3f} / {az:.3f} deg")
    if abs(s["sun_elevation_deg"] - el) > 0.6 or abs((s["sun_azimuth_deg"] - az + 180) % 360 - 180) > 0.6:
        fail("the sun is not within 0.6 deg of the NOAA equations")
    unsupported = s["cigi"]["unsupported"]
    print("cigi:", json.dumps(s["cigi"]))
    if unsupported.get("4") != 1 or unsupported.get("35") != 1:
        fail(f"cigi.unsupported {unsupported}: expected opcodes 4 and 35 once each")
    with open(os.path.join(out, "serve", "frames.csv")) as f:
        header = f.readline().strip().split(",")
        rows = [line.strip().split(",") for line in f]
    vis = [float(r[header.index("visibility_m")]) for r in rows]
    if vis[0] != 5000.0 or vis[-1] != 5000.0:
        fail(f"frames.csv visibility_m {vis[0]} .. {vis[-1]}, expected 5000 from frame 0")
    clouds = [k for k, r in enumerate(rows) if "clouds" in r[header.index("passes")]]
    print("frames with the cloud pass:", clouds)
    if clouds != list(range(3, 7)):
        fail(f"the cloud layer drawn in frames {clouds}, expected 3..6 (set in frame 3, removed in frame 7)")
    rejected = s["cigi"]["rejected"]
    if rejected.get("weather-cloud-layer") != 1 or rejected.get("weather-cloud-type") != 1:
        fail(f"cigi.rejected {rejected}: expected one bad cloud layer and one cloud type 'other'")
    if failures:
        return 1
    print("PASS environment")
    return 0


if __name__ == "__main__":
    sys.exit(main())
