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
for n in [10, 100, 1800, 10000]:
    for f in ["chain", "assembly"]:
        bench(f"arch dead load, N = {n}, D = 1.0747 ({f})", "/arch/dead-load", {"geometry": {"kind": "circular", "radius": 10, "thickness": 1.0747, "voussoirs": n}, "formulation": f}, lambda d: d["solver"]["time_ms"])
    bench(f"arch live load, N = {n}, D = 1.5 (chain)", "/arch/live-load", {"geometry": {"kind": "circular", "radius": 10, "thickness": 1.5, "voussoirs": n}, "loads": [{"block": n // 4 + 1, "fy": -1}]}, lambda d: d["solver"]["time_ms"])
for n in [100, 1800]:
    bench(f"minimum thickness, semicircle, N = {n}", "/arch/minimum-thickness", {"geometry": {"kind": "circular", "radius": 10, "thickness": 1, "voussoirs": n}}, lambda d: d["solve_time_ms"])
