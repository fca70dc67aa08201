#!/usr/bin/env python3
"""Writes a scene moved by an offset: every body's position and keyframes (a mesh's vertices
are local to its position; an attached sensor's position is an offset and stays).
usage: shift_scene.py IN.json OUT.json DX DY DZ [DESCRIPTION]"""
import json
import sys

src, dst, dx, dy, dz = sys.argv[1], sys.argv[2], *map(float, sys.argv[3:6])
scene = json.load(open(src))
if len(sys.argv) > 6:
    scene["description"] = sys.argv[6]
for b in scene["bodies"]:
    if "attached_to" in b:
        continue
    if "keyframes" in b:
        for k in b["keyframes"]:
            k["position"] = [k["position"][0] + dx, k["position"][1] + dy, k["position"][2] + dz]
    else:
        p = b.get("position", [0, 0, 0])
        b["position"] = [p[0] + dx, p[1] + dy, p[2] + dz]
with open(dst, "w") as f:
    f.write(json.dumps(scene, indent=1) + "\n")
