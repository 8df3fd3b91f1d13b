#!/usr/bin/env python3
"""Checks a command's --help text (stdin): the usage synopsis comes first, and
every option the synopsis names is described below it with a sentence.
   ig run --help | check_help.py "ig run"
Prints "help ok: N options described" or FAIL lines (exit 1)."""
import re
import sys

command = sys.argv[1]
text = sys.stdin.read()
fails = []
if not text.startswith("usage: " + command):
    fails.append(f"help does not start with 'usage: {command}'")
head, sep, described = text.partition("\noptions:\n")
if not sep:
    fails.append("no 'options:' section")
synopsis = set(re.findall(r"(?<![\w-])(--[a-z][a-z0-9-]*)", head))
# Option blocks: "  --name [VALUE]   description", the description maybe on the next lines.
blocks = {}
name = None
for line in described.splitlines():
    m = re.match(r"  (--[a-z][a-z0-9-]*)(?: \S+)?(?:\s{2,}(\S.*))?$", line)
    if m:
        name = m.group(1)
        blocks[name] = m.group(2) or ""
    elif name and line.startswith(" " * 26):
        blocks[name] += " " + line.strip()
for option in sorted(synopsis):
    if option not in blocks:
        fails.append(f"{option} is in the synopsis but not described")
for option, description in blocks.items():
    if len(description.split()) < 3:
        fails.append(f"{option}: no description ('{description}')")
for f in fails:
    print("FAIL:", f)
if fails:
    sys.exit(1)
print(f"help ok: {len(blocks)} options described, {len(synopsis)} in the synopsis")
