#!/usr/bin/env python3
"""Every ```json block of docs/*.md works as written.

   check_doc_examples.py IG SRC_DIR OUT_DIR

* A complete scenario (an object with "terrain" and "path") is saved as
  OUT_DIR/<doc>_<line>/scenario.json and run with
  `ig run scenario.json --frames 1 --size 160x120`. A ```sh block right
  before it is the example's set-up (e.g. making the image it drapes) and is
  run first in that folder, as a reader would.
* A fragment ("key": {...}, one or more top-level scenario members) must be
  JSON once wrapped in braces, name only top-level scenario keys, and run
  when it replaces those members of a small base scenario (generated terrain
  georeferenced where the geodetic path fragment lies, 12 s long for the
  capture fragment).
* An example that uses $IG_DEM_DIR (or ${IG_DEM_DIR}) is skipped, with a
  line saying so, when the variable is not set.
* A model table (docs/models.md: "entities" whose items have "lods") names
  only files the build writes beside the binary (bin/models), finest first.
Prints one line per example and "doc examples ok: ..." or FAIL lines (exit 1).
"""
import glob
import json
import os
import re
import shutil
import subprocess
import sys

ig, src, out = (os.path.abspath(a) for a in sys.argv[1:4])
TOP_LEVEL = {"name", "terrain", "render", "environment", "channels", "path", "entities", "time", "capture", "live"}
MODELS = os.path.join(os.path.dirname(ig), "models")  # the model table's folder beside the binary
BASE = {
    "terrain": {"generator": {"size": 257, "origin": [36.66, -118.13]}},
    "path": {"keys": [{"t": 0, "position": [1000, 1000, 2500]}]},
    "time": {"step_s": 0.5, "duration_s": 12},
}
BLOCK = re.compile(r"^```(\w*)\n(.*?)^```", re.S | re.M)

fails, ran, skipped = [], 0, 0


def run_ig(folder, label):
    global ran
    r = subprocess.run([ig, "run", "scenario.json", "--frames", "1", "--size", "160x120", "--out", "out", "--quiet"],
                       cwd=folder, capture_output=True, text=True)
    ran += 1
    if r.returncode != 0:
        fails.append(f"{label}: ig run exit {r.returncode}: {r.stderr.strip()}")
        return
    print(f"{label}: runs")


shutil.rmtree(out, ignore_errors=True)
for doc in sorted(glob.glob(os.path.join(src, "docs", "*.md"))):
    text = open(doc).read()
    blocks = list(BLOCK.finditer(text))
    for k, m in enumerate(blocks):
        if m.group(1) != "json":
            continue
        line = text[: m.start()].count("\n") + 1
        name = os.path.basename(doc)
        label = f"{name}:{line}"
        body = m.group(2)
        folder = os.path.join(out, f"{name[:-3]}_{line}")
        if "IG_DEM_DIR" in body and not os.environ.get("IG_DEM_DIR"):
            print(f"{label}: skipped (IG_DEM_DIR is not set)")
            skipped += 1
            continue
        try:
            value = json.loads(body)
            fragment = False
        except json.JSONDecodeError:
            try:
                value = json.loads("{" + body + "}")
                fragment = True
            except json.JSONDecodeError as e:
                fails.append(f"{label}: not JSON, not even as members of an object: {e}")
                continue
        if not isinstance(value, dict):
            fails.append(f"{label}: a {type(value).__name__}, not a scenario or scenario members")
            continue
        if not fragment and isinstance(value.get("entities"), list) and all("lods" in e for e in value["entities"]):
            # A model table (docs/models.md): every file it names is one the build makes, levels finest first.
            missing = [lod["file"] for e in value["entities"] for lod in e["lods"]
                       if not os.path.exists(os.path.join(MODELS, lod["file"]))]
            sizes = [[lod["min_size_px"] for lod in e["lods"]] for e in value["entities"]]
            if missing or any(a <= b for s in sizes for a, b in zip(s, s[1:])):
                fails.append(f"{label}: model table: files not in {MODELS}: {missing}; levels {sizes}")
            else:
                print(f"{label} (model table): every file in {MODELS}")
                ran += 1
            continue
        unknown = set(value) - TOP_LEVEL
        if unknown:
            fails.append(f"{label}: not scenario keys: {sorted(unknown)}")
            continue
        complete = not fragment and "terrain" in value and "path" in value
        os.makedirs(folder)
        if complete:
            # A ```sh block just before the example (only blank lines or text
            # without code between) is its set-up.
            if k > 0 and blocks[k - 1].group(1) == "sh" and "```" not in text[blocks[k - 1].end(): m.start()] \
                    and text[blocks[k - 1].end(): m.start()].strip() == "":
                r = subprocess.run(["bash", "-euo", "pipefail", "-c", blocks[k - 1].group(2)], cwd=folder,
                                   capture_output=True, text=True)
                if r.returncode != 0:
                    fails.append(f"{label}: its set-up failed: {r.stderr.strip()}")
                    continue
            scenario = value
        else:
            scenario = dict(BASE)
            scenario.update(value)
        with open(os.path.join(folder, "scenario.json"), "w") as f:
            json.dump(scenario, f, indent=1)
        run_ig(folder, label + (" (complete scenario)" if complete else f" (fragment: {', '.join(value)})"))

for f in fails:
    print("FAIL:", f)
if fails:
    sys.exit(1)
print(f"doc examples ok: {ran} run, {skipped} skipped")
