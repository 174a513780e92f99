"""HTTP round trips against a running thrustline: the solve time the service reports and the
whole request's wall time, median of 15 requests each, for the README's Performance table.

Usage: python3 bench/http_timing.py [BASE_URL]   (default http://127.0.0.1:8080)
"""
import json, statistics, sys, time, urllib.request
base = sys.argv[1] if len(sys.argv) > 1 else "http://127.0.0.1:8080"
def post(path, body):
    req = urllib.request.Request(base + path, data=json.dumps(body).encode(), headers={"content-type": "application/json"})
    t = time.perf_counter()
    with urllib.request.urlopen(req) as r:
        d = json.load(r)
    return d, (time.perf_counter() - t) * 1e3
def bench(name, path, body, key):
    rt, st = [], []
    for _ in range(15):
        d, ms = post(path, body)
        rt.append(ms); st.append(key(d))
    print(f"| {name} | {statistics.median(st):.2f} ms | {statistics.median(rt):.2f} ms |")
sp = {"slope": {"height": 30.48, "length": 60.96}, "circle": {"x": 9.63168, "y": 63.76416}, "soil": {"unit_weight": 10, "cohesion": 6.096, "friction_angle_deg": 40, "pore_pressure_ratio": 0.5}}
for n in [100, 1000]:
    bench(f"Spencer, one circle, {n} slices", "/slope/spencer", dict(sp, slices=n), lambda d: d["solve_time_ms"])
for n in [21, 50]:
    bench(f"Spencer critical circle, {n} × {n} grid + refinement, 50 slices", "/slope/spencer", dict(sp, slices=50, circle=None, search={"nx": n, "ny": n}), lambda d: d["solve_time_ms"])
for n in [10, 100, 1800, 10000]:
    for f in ["chain", "assembly"]:
        bench(f"arch dead load, N = {n}, D = 1.0747 ({f})", "/arch/dead-load", {"geometry": {"kind": "circular", "radius": 10, "thickness": 1.0747, "voussoirs": n}, "formulation": f}, lambda d: d["solver"]["time_ms"])
    bench(f"arch live load, N = {n}, D = 1.5 (chain)", "/arch/live-load", {"geometry": {"kind": "circular", "radius": 10, "thickness": 1.5, "voussoirs": n}, "loads": [{"block": n // 4 + 1, "fy": -1}]}, lambda d: d["solver"]["time_ms"])
for n in [100, 1800]:
    bench(f"minimum thickness, semicircle, N = {n}", "/arch/minimum-thickness", {"geometry": {"kind": "circular", "radius": 10, "thickness": 1, "voussoirs": n}}, lambda d: d["solve_time_ms"])

# Part II scenes.
layered = {"section": {"ground": [[-20, 0], [0, 0], [20, 10], [40, 10]],
    "layers": [{"top": None, "soil": {"unit_weight": 19, "cohesion": 10, "friction_angle_deg": 28}},
               {"top": [[-20, -3], [40, -3]], "soil": {"unit_weight": 20, "cohesion": 0, "friction_angle_deg": 35}},
               {"top": [[-20, -6], [40, -8]], "soil": {"unit_weight": 21, "cohesion": 20, "friction_angle_deg": 25}}],
    "piezometric_line": [[-20, 1], [10, 3], [40, 6]]}}
bench("section, 3 layers + water table, one circle, 100 slices", "/slope/spencer", dict(layered, circle={"centre": [12, 28], "radius": 26}, slices=100), lambda d: d["solve_time_ms"])
bench("same, with Morgenstern–Price, Bishop, Janbu and ordinary", "/slope/spencer", dict(layered, circle={"centre": [12, 28], "radius": 26}, slices=100, methods=["morgenstern_price", "bishop", "janbu", "ordinary"]), lambda d: d["solve_time_ms"])
fk = {"section": {"ground": [[0, 60], [60, 60], [140, 20], [180, 20]], "layers": [{"top": None, "soil": {"unit_weight": 120, "cohesion": 600, "friction_angle_deg": 20}}]}}
# 20 points on Fredlund & Krahn's case-1 circle (centre (120, 90), R = 80), ends above the ground.
surface = [[45 + 114 * i / 19, 90 - (6400 - (45 + 114 * i / 19 - 120) ** 2) ** 0.5] for i in range(20)]
bench("F&K section, a 20-vertex polyline surface, 100 slices", "/slope/spencer", dict(fk, surface=surface, slices=100), lambda d: d["solve_time_ms"])
bench("same, with Morgenstern–Price, Bishop, Janbu and ordinary (moment centre given)", "/slope/spencer", dict(fk, surface=surface, slices=100, moment_centre=[120, 90], methods=["morgenstern_price", "bishop", "janbu", "ordinary"]), lambda d: d["solve_time_ms"])
acads = {"section": {"ground": [[20, 25], [30, 25], [50, 35], [70, 35]], "layers": [{"top": None, "soil": {"unit_weight": 20, "cohesion": 3, "friction_angle_deg": 19.6}}]}}
bench("ACADS 1(a) search {}: 21 × 21 centres × 10 radii + refinement, 50 slices", "/slope/spencer", dict(acads, search={}, slices=50), lambda d: d["solve_time_ms"])
seam = {"section": {"ground": [[10, 50], [15, 50], [19, 48], [31.9, 41.55], [32, 41.5], [35, 41.5]],
    "layers": [{"top": None, "soil": {"unit_weight": 19, "cohesion": 15, "friction_angle_deg": 20}},
               {"top": [[10, 48.5], [19, 48], [32, 41.5], [35, 41.5]], "soil": {"unit_weight": 19, "cohesion": 17, "friction_angle_deg": 21}},
               {"top": [[10, 46.25], [31.9, 41.55], [32, 41.5], [35, 41.5]], "soil": {"unit_weight": 19, "cohesion": 5, "friction_angle_deg": 10}},
               {"top": [[10, 46.2], [32, 41.5], [35, 41.5]], "soil": {"unit_weight": 19, "cohesion": 35, "friction_angle_deg": 28}}]}}
bench("non-circular search, Cheng et al. ex. 4 (5 cm seam), 12 vertices, 50 slices", "/slope/spencer", dict(seam, search={"shape": "noncircular"}, slices=50), lambda d: d["solve_time_ms"])
bench("3-layer section search: 50 × 50 centres × 10 radii + refinement, 50 slices", "/slope/spencer", dict(layered, search={"nx": 50, "ny": 50, "nr": 10}, slices=50), lambda d: d["solve_time_ms"])
arch = {"geometry": {"kind": "circular", "radius": 10, "thickness": 1.0, "voussoirs": 100}, "fill": {"unit_weight": 1.8, "surface": 11.5}}
bench("arch with fill, N = 100, a road load (chain)", "/arch/live-load", dict(arch, road_loads=[{"x": -4, "fy": -10, "length": 0.3}]), lambda d: d["solver"]["time_ms"])
bench("arch with fill, N = 100, two axles rolled over 101 stops", "/arch/live-load", dict(arch, rolling={"axles": [{"offset": 0, "fy": -10}, {"offset": 1.8, "fy": -10}], "x_start": -12, "x_end": 10, "positions": 101}), lambda d: d["rolling"]["time_per_position_ms"] * 101)
passive = dict(arch, fill=dict(arch["fill"], passive={"friction_angle_deg": 30, "mobilisation": 0.5}))
bench("arch with fill and passive restraint (m = 0.5), N = 100, a road load (assembly)", "/arch/live-load", dict(passive, road_loads=[{"x": -4, "fy": -10, "length": 0.3}]), lambda d: d["solver"]["time_ms"])
bench("same, two axles rolled over 101 stops", "/arch/live-load", dict(passive, rolling={"axles": [{"offset": 0, "fy": -10}, {"offset": 1.8, "fy": -10}], "x_start": -12, "x_end": 10, "positions": 101}), lambda d: d["rolling"]["time_per_position_ms"] * 101)
quarter = {"geometry": {"kind": "circular", "radius": 10, "thickness": 1.5, "voussoirs": 100}, "loads": [{"block": 26, "fy": -1}]}
bench("arch live load, N = 100, crushing σ_c = 100 (cutting planes from 4)", "/arch/live-load", dict(quarter, compressive_strength=100), lambda d: d["solver"]["time_ms"])
bench("the same with 8 starting planes", "/arch/live-load", dict(quarter, compressive_strength=100, crushing_planes=8), lambda d: d["solver"]["time_ms"])
bench("arch live load, N = 100, crushing σ_c = 50", "/arch/live-load", dict(quarter, compressive_strength=50), lambda d: d["solver"]["time_ms"])

# Assemblies (model §5.4–5.5).
rings = {"geometry": {"kind": "circular", "radius": 10, "thickness": 1.5, "voussoirs": 100, "rings": 2}, "ring_friction_coefficient": 0.6}
bench("two staggered rings, 2 × 100 voussoirs, ring μ = 0.6: dead load", "/arch/dead-load", rings, lambda d: d["solver"]["time_ms"])
bench("the same: live load on inner-ring block 26 (associative solve; the friction check adds its steps)", "/arch/live-load", dict(rings, loads=[{"block": 26, "fy": -1}]), lambda d: d["solver"]["time_ms"])
bench("two staggered rings, 2 × 100, without ring friction: dead load (a self-stress at the springings: the least-normal-force state too)", "/arch/dead-load", {"geometry": rings["geometry"]}, lambda d: d["solver"]["time_ms"])
bench("the same: live load on inner-ring block 26 (nothing slides: no friction check)", "/arch/live-load", {"geometry": rings["geometry"], "loads": [{"block": 26, "fy": -1}]}, lambda d: d["solver"]["time_ms"])
spans = {"geometry": {"kind": "circular", "radius": 10, "thickness": 1.5, "voussoirs": 60, "spans": 3, "pier_width": 4, "pier_height": 6}}
bench("three spans × 60 voussoirs on two piers: live load on block 16", "/arch/live-load", dict(spans, loads=[{"block": 16, "fy": -1}]), lambda d: d["solver"]["time_ms"])
filled_spans = {"geometry": dict(spans["geometry"], rings=2, ring_joints="aligned"),
    "fill": {"unit_weight": 1.8, "surface": 12.5, "passive": {"friction_angle_deg": 30, "mobilisation": 0.3}}}
bench("the same as two aligned rings under fill with passive restraint (m = 0.3): a road load", "/arch/live-load", dict(filled_spans, road_loads=[{"x": 4, "fy": -10, "length": 0.3}]), lambda d: d["solver"]["time_ms"])
wall = {"geometry": {"kind": "assembly",
    "blocks": [{"polygon": [[0, 0], [0.5, 0], [0.5, 2], [0, 2]]}, {"polygon": [[0.5, 0], [1, 0], [1, 2], [0.5, 2]]}, {"polygon": [[0, 2], [1, 2], [1, 2.5], [0, 2.5]]}],
    "supports": [{"polygon": [[-2, -1], [3, -1], [3, 0], [-2, 0]]}]},
    "friction_coefficient": 0.5, "friction": "non_associative", "loads": [{"block": 3, "x": 0, "y": 2.5, "fx": 1}]}
bench("two leaves under a cap, non-associative (whole request: its steps)", "/arch/live-load", wall, lambda d: d["solver"]["time_ms"])
bench("the same with friction_relaxation anderson", "/arch/live-load", dict(wall, friction_relaxation="anderson"), lambda d: d["solver"]["time_ms"])
narrow = dict(wall, friction_coefficient=0.9, loads=[{"block": 3, "x": 0, "y": 1.5, "fx": 1}],
    geometry=dict(wall["geometry"], blocks=[{"polygon": [[0, 0], [0.3, 0], [0.3, 1], [0, 1]]}, {"polygon": [[0.3, 0], [0.6, 0], [0.6, 1], [0.3, 1]]}, {"polygon": [[0, 1], [0.6, 1], [0.6, 1.5], [0, 1.5]]}]))
bench("leaves 0.3 × 1 under a cap, μ = 0.9, non-associative (the paper's 50 steps, then the mixing's)", "/arch/live-load", narrow, lambda d: d["solver"]["time_ms"])
courses = [[0, 1, 2, 3], [0, 0.5, 1.5, 2.5, 3], [0, 1, 2, 3]]
bricks = [[[a, 0.5 * c], [b, 0.5 * c], [b, 0.5 * c + 0.5], [a, 0.5 * c + 0.5]] for c, xs in enumerate(courses) for a, b in zip(xs, xs[1:])]
panel = {"geometry": {"kind": "assembly", "blocks": [{"polygon": p} for p in bricks], "supports": [{"polygon": [[-2, -1], [5, -1], [5, 0], [-2, 0]]}]},
    "friction_coefficient": 0.5, "friction": "non_associative",
    "loads": [{"block": i + 1, "x": (p[0][0] + p[1][0]) / 2, "y": p[0][1] + 0.25, "fx": (p[1][0] - p[0][0]) * 0.5} for i, p in enumerate(bricks)]}
bench("running-bond panel 3 courses × 3 bricks, sideways λ × weight, μ = 0.5, non-associative (its steps, then the associative state)", "/arch/live-load", panel, lambda d: d["solver"]["time_ms"])

# Studies (issue 43): the whole request's solve time, the deterministic answer included.
cohesion = {"field": "soil.cohesion", "distribution": "normal", "std": 1.0, "min": 0}
friction = {"field": "soil.friction_angle_deg", "distribution": "lognormal", "std": 3}
bench("probabilistic: 10,000 samples on the fixed 100-slice circle (2 variables, Monte Carlo)", "/slope/spencer",
      dict(sp, slices=100, include=[], probabilistic={"samples": 10000, "variables": [cohesion, friction]}), lambda d: d["solve_time_ms"])
bench("probabilistic: 1,000 samples, each re-running the 21 × 21 search, 50 slices", "/slope/spencer",
      dict(sp, slices=50, circle=None, search={"nx": 21, "ny": 21}, include=[],
           probabilistic={"samples": 1000, "surface": "search", "variables": [cohesion, friction]}), lambda d: d["solve_time_ms"])
bench("sensitivity: 2 variables × 11 values, each re-running the 21 × 21 search, 50 slices", "/slope/spencer",
      dict(sp, slices=50, circle=None, search={"nx": 21, "ny": 21}, include=[],
           sensitivity={"variables": [{"field": "soil.cohesion", "from": 4, "to": 8}, {"field": "soil.friction_angle_deg", "from": 30, "to": 45}]}), lambda d: d["solve_time_ms"])
