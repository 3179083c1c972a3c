#!/usr/bin/env python3
"""Write union_N.scad for the scaling series: N primitives (alternating
spheres, cubes and cylinders) on a jittered cubic grid, all one union.
Usage: gen_union.py N OUT.scad"""
import math
import random
import sys

n, out = int(sys.argv[1]), sys.argv[2]
rng = random.Random(7)  # fixed: every run benchmarks the same scene
side = math.ceil(n ** (1 / 3))
lines = [f"// {n} primitives on a {side}^3 grid, one union (bench/scenes/gen_union.py)"]
for i in range(n):
    x, y, z = i % side, (i // side) % side, i // (side * side)
    p = [10 * c + rng.uniform(-2, 2) for c in (x, y, z)]
    t = f"translate([{p[0]:.3f}, {p[1]:.3f}, {p[2]:.3f}])"
    k = i % 3
    if k == 0:
        lines.append(f"{t} sphere({rng.uniform(3, 5):.3f});")
    elif k == 1:
        lines.append(f"{t} rotate([{rng.uniform(0, 90):.1f}, {rng.uniform(0, 90):.1f}, 0]) cube({rng.uniform(4, 7):.3f}, center = true);")
    else:
        lines.append(f"{t} cylinder(r = {rng.uniform(2, 4):.3f}, h = {rng.uniform(4, 8):.3f}, center = true);")
open(out, "w").write("\n".join(lines) + "\n")
