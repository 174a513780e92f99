"""Whole-request times of two running thrustline servers side by side, alternating, median of
15 (ms): what a change did to requests that do not use its options.

Usage: python3 bench/side_by_side.py OLD_URL NEW_URL
"""
import json, statistics, sys, time, urllib.request


def post(base, path, body):
    req = urllib.request.Request(base + path, data=json.dumps(body).encode(),
                                 headers={"content-type": "application/json"})
    t = time.perf_counter()
    with urllib.request.urlopen(req) as r:
        r.read()
    return (time.perf_counter() - t) * 1e3


circle = {"kind": "circular", "radius": 10.0, "thickness": 1.0, "voussoirs": 100}
cases = [
    ("live load, N = 100", "/arch/live-load",
     {"geometry": dict(circle, thickness=1.5), "loads": [{"block": 26, "fy": -1}], "include": []}),
    ("dead load, N = 1800 (Milankovitch)", "/arch/dead-load",
     {"geometry": dict(circle, thickness=1.0747, voussoirs=1800), "include": []}),
    ("101 rolling stops", "/arch/live-load",
     {"geometry": circle, "fill": {"unit_weight": 1.8, "surface": 11.5}, "include": [],
      "rolling": {"axles": [{"offset": 0.0, "fy": -10.0}, {"offset": 1.8, "fy": -10.0}],
                  "x_start": -12.0, "x_end": 10.0, "positions": 101}}),
    ("two rings (assembly)", "/arch/live-load",
     {"geometry": dict(circle, thickness=1.5, voussoirs=40, rings=2),
      "ring_friction_coefficient": 0.6, "loads": [{"block": 10, "fy": -1}], "include": []}),
    ("minimum thickness, N = 200", "/arch/minimum-thickness",
     {"geometry": dict(circle, voussoirs=200)}),
    ("passive fill", "/arch/live-load",
     {"geometry": dict(circle, voussoirs=60), "include": [],
      "fill": {"unit_weight": 1.8, "surface": 11.5,
               "passive": {"friction_angle_deg": 30, "mobilisation": 0.5}},
      "road_loads": [{"x": -4, "fy": -10}]}),
]
bases = sys.argv[1:]
print("| request | " + " | ".join(bases) + " |")
for name, path, body in cases:
    for base in bases:
        post(base, path, body)
    times = {b: [] for b in bases}
    for _ in range(15):
        for b in bases:
            times[b].append(post(b, path, body))
    print(f"| {name} | " + " | ".join(f"{statistics.median(times[b]):.2f}" for b in bases) + " |")
