"""Slope searches on two (or more) running thrustline servers side by side, alternating, the
solve time each reports, median of 15 (ms): the rows of docs/performance.md's circle-search
tables.

Usage: python3 bench/slope_searches.py OLD_URL NEW_URL
"""
import json, statistics, sys, urllib.request


def post(base, body):
    req = urllib.request.Request(base + "/slope/spencer", data=json.dumps(body).encode(),
                                 headers={"content-type": "application/json"})
    with urllib.request.urlopen(req) as r:
        return json.load(r)["solve_time_ms"]


simple = {"slope": {"height": 30.48, "length": 60.96},
          "soil": {"unit_weight": 10, "cohesion": 6.096, "friction_angle_deg": 40, "pore_pressure_ratio": 0.5},
          "slices": 50, "search": {"nx": 50, "ny": 50}, "include": []}
layered = {"section": {"ground": [[-20, 0], [0, 0], [20, 10], [40, 10]],
    "layers": [{"top": None, "soil": {"unit_weight": 19, "cohesion": 10, "friction_angle_deg": 28}},
               {"top": [[-20, -3], [40, -3]], "soil": {"unit_weight": 20, "cohesion": 0, "friction_angle_deg": 35}},
               {"top": [[-20, -6], [40, -8]], "soil": {"unit_weight": 21, "cohesion": 20, "friction_angle_deg": 25}}],
    "piezometric_line": [[-20, 1], [10, 3], [40, 6]]},
    "search": {"nx": 50, "ny": 50, "nr": 10}, "slices": 50, "include": []}
acads = {"section": {"ground": [[20, 25], [30, 25], [50, 35], [70, 35]],
    "layers": [{"top": None, "soil": {"unit_weight": 20, "cohesion": 3, "friction_angle_deg": 19.6}}]},
    "search": {}, "slices": 50, "include": []}
cases = [("simple 21 × 21 search, 50 slices", dict(simple, search={"nx": 21, "ny": 21})),
         ("simple 50 × 50 search, 50 slices", simple),
         ("ACADS 1(a) search {}", acads),
         ("3-layer section search, 50 × 50 × 10", layered)]
bases = sys.argv[1:]
for name, body in cases:
    times = {b: [] for b in bases}
    for _ in range(15):
        for b in bases:
            times[b].append(post(b, body))
    print(f"| {name} | " + " | ".join(f"{statistics.median(v):.2f}" for v in times.values()) + " |")
