#!/usr/bin/python3
"""The solver's layers, as the README lists them, hold in the code (issue 29).

Reads the numbered list between '<!-- layers -->' and '<!-- /layers -->' in README.md: each line
'N. `folder`, `folder` - ...' puts folders of solver/fe on layer N (1 = bottom). Every
'#include "folder/..."' in solver/fe must name a folder on the same or a lower layer, every folder
of solver/fe must be on a layer, and the plain C++ parts (closed forms, mechanisms, fatigue,
nonlinear, text) must not include deal.II. Prints every violation; exit 1 if any."""
import os
import re
import sys

root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", ".."))
readme = open(os.path.join(root, "README.md")).read()
block = re.search(r"<!-- layers -->(.*?)<!-- /layers -->", readme, re.S)
if not block:
    sys.exit("FAIL: README.md has no <!-- layers --> list")
layer = {}
for line in block.group(1).splitlines():
    m = re.match(r"\s*(\d+)\.\s+(.*)", line)
    if m:
        for folder in re.findall(r"`([a-z_]+)`", m.group(2).split(" - ")[0]):
            layer[folder] = int(m.group(1))
fe = os.path.join(root, "solver", "fe")
problems = []
folders = sorted(d for d in os.listdir(fe) if os.path.isdir(os.path.join(fe, d)))
for folder in folders:
    if folder not in layer:
        problems.append("solver/fe/%s is on no layer of the README's list" % folder)
include = re.compile(r'^\s*#\s*include\s+"([a-z_]+)/', re.M)
count = 0
for folder in folders:
    for dirpath, _, files in os.walk(os.path.join(fe, folder)):
        for name in files:
            if not name.endswith((".h", ".cc")):
                continue
            path = os.path.join(dirpath, name)
            for target in include.findall(open(path, errors="replace").read()):
                count += 1
                if target in layer and folder in layer and layer[target] > layer[folder]:
                    problems.append("%s includes %s/ (layer %d above its own %d)"
                                    % (os.path.relpath(path, root), target, layer[target], layer[folder]))
plain = [os.path.join(root, "solver", d) for d in ("closed_forms", "mechanisms", "fatigue", "text")] + [os.path.join(fe, "nonlinear")]
for top in plain:
    for dirpath, _, files in os.walk(top):
        for name in files:
            if name.endswith((".h", ".cc")) and "<deal.II/" in open(os.path.join(dirpath, name), errors="replace").read():
                problems.append("%s includes deal.II (plain C++ part)" % os.path.relpath(os.path.join(dirpath, name), root))
for p in problems:
    print(p)
print("%d folders on %d layers, %d includes between folders checked" % (len(folders), len(set(layer.values())), count))
if problems:
    sys.exit("FAIL: %d layer violations" % len(problems))
print("PASS")
