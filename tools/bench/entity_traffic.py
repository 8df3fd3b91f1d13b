#!/usr/bin/env python3
"""Writes a scenario with N scripted entities in view of the ownship: the base
scenario's flight, plus traffic flying the ownship's own path (local or geodetic) 2 to 12 s ahead
of it, spread left and right and up (types 1, 2, 3 in turn: aircraft,
ground vehicles and ships, the last two clamped to the ground beside the
path). Deterministic: entity k's place depends on k only.

  entity_traffic.py BASE.json N OUT.json
"""
import json
import math
import os
import sys


def main():
    base, n, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    s = json.load(open(base))
    keys = s["path"]["keys"]
    agl = s["path"].get("altitude", "msl") == "agl"
    geodetic = s["path"].get("frame", "local") == "geodetic"
    entities = []
    for k in range(n):
        etype = 1 + k % 3
        ahead = 2.0 + 10.0 * ((k * 0.618034) % 1.0)        # seconds ahead on the ownship's path
        side = (((k * 0.414214) % 1.0) - 0.5) * 400.0        # metres left / right of the path
        up = 20.0 + 60.0 * ((k * 0.732051) % 1.0)            # metres above the ownship (aircraft)
        ekeys = []
        for i, key in enumerate(keys):
            t = key["t"]
            # The ownship's position `ahead` seconds later, by linear steps.
            ta = min(t + ahead, keys[-1]["t"])
            j = max(m for m in range(len(keys)) if keys[m]["t"] <= ta)
            a, b = keys[j], keys[min(j + 1, len(keys) - 1)]
            f = 0.0 if b["t"] == a["t"] else (ta - a["t"]) / (b["t"] - a["t"])
            p = [a["position"][c] + f * (b["position"][c] - a["position"][c]) for c in range(3)]
            h = math.radians(key.get("hpr", [0, 0, 0])[0])
            east, north = side * math.cos(h), -side * math.sin(h)
            if geodetic:  # metres to degrees (spherical: enough to spread traffic)
                p[0] += north / 111320.0
                p[1] += east / (111320.0 * math.cos(math.radians(p[0])))
            else:
                p[0] += east
                p[1] += north
            hpr = [key.get("hpr", [0, 0, 0])[0], 0.0, 0.0]
            if etype == 1:
                p[2] += up
                ekeys.append({"t": t, "position": p, "hpr": hpr})
            else:
                ekeys.append({"t": t, "position": [p[0], p[1], 0.0], "hpr": hpr})
        e = {"id": k + 1, "type": etype,
             "path": {"frame": "geodetic" if geodetic else "local", "altitude": "agl" if agl else "msl", "keys": ekeys}}
        if etype != 1:  # on the ground beside the path: clamped, 0 m above it
            e["clamp"] = "ground"
            e["path"]["altitude"] = "msl"
        entities.append(e)
    s["entities"] = entities
    s["name"] = f"{s.get('name', os.path.splitext(os.path.basename(base))[0])}_traffic_{n}"
    # Paths in the base file stay valid from the output's folder.
    here = os.path.dirname(os.path.abspath(base))
    if "terrain" in s and "file" in s["terrain"] and not os.path.isabs(s["terrain"]["file"]) \
            and "$" not in s["terrain"]["file"]:
        s["terrain"]["file"] = os.path.join(here, s["terrain"]["file"])
    json.dump(s, open(out, "w"), indent=1)


if __name__ == "__main__":
    main()
