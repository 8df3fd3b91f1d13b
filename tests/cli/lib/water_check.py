#!/usr/bin/env python3
"""Checks of what terrain.water found, for tests/cli/water.cmake.

  water_check.py info-sierra < (ig info sierra ...)   the Sierra's lakes
  water_check.py info-fuji < (ig info fuji ...)       Suruga Bay, the sea
  water_check.py summary SUMMARY BODIES SUFFIX        summary.json's water
  water_check.py no-water SUMMARY                     summary.json: none
"""
import json
import sys


def main():
    mode = sys.argv[1]
    if mode in ("info-sierra", "info-fuji"):
        w = json.load(sys.stdin)["water"]
        bodies = w["list"]
        print(w["source"], w["bodies"], [b["level_m"] for b in bodies[:3]])
        assert w["source"] == "auto"
        if mode == "info-sierra":
            # Tahoe the largest (74 995 samples at 1 899 m), Mono Lake next;
            # nothing at or below sea level (Death Valley is dry).
            assert w["bodies"] > 400
            assert bodies[0]["kind"] == "lake" and bodies[0]["level_m"] == 1899
            assert 74000 < bodies[0]["samples"] <= 74995
            assert bodies[1]["level_m"] == 1943
            assert min(b["level_m"] for b in bodies) > 0
        else:
            assert bodies[0]["kind"] == "sea" and bodies[0]["level_m"] == 0
            assert bodies[0]["samples"] > 55000
    elif mode == "summary":
        w = json.load(open(sys.argv[2]))["water"]
        print(w)
        assert w["bodies"] == int(sys.argv[3]) and w["source"].endswith(sys.argv[4]) and w["area_km2"] > 0
    elif mode == "no-water":
        assert json.load(open(sys.argv[2]))["water"] is None
    else:
        sys.exit("unknown mode " + mode)
    print("water ok")


if __name__ == "__main__":
    main()
