"""Thrustline against what an engineer would otherwise use, measured side by side in one run:
scipy's HiGHS on the arch limit-analysis programmes (Livesley's assembly formulation, written
independently in bench/highs_compare.py) and PySlope's critical-circle search (Bishop's method)
on the dry 2:1 embankment. Prints the table docs/performance.md quotes, every figure a ratio.

Usage: python3 bench/peers.py [BASE_URL]   (default http://127.0.0.1:8080; start `thrustline
serve` first; installs numpy, scipy and pyslope from PyPI if they are missing)
"""
import json
import os
import statistics
import sys
import urllib.request

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import highs_compare  # noqa: E402
import pyslope_compare  # noqa: E402

BASE = sys.argv[1] if len(sys.argv) > 1 else "http://127.0.0.1:8080"
highs_compare.BASE = BASE


def post(path, body):
    request = urllib.request.Request(BASE + path, data=json.dumps(body).encode(),
                                     headers={"content-type": "application/json"})
    with urllib.request.urlopen(request) as response:
        return json.load(response)


def ours(path, body, runs, key):
    answers = [post(path, body) for _ in range(runs)]
    return answers[-1], statistics.median(key(a) for a in answers)


print("| problem | peer | peer's time | thrustline's solve time | ratio |")
print("|---|---|---|---|---|")
for n in (100, 1800, 10000):
    runs = 3 if n >= 10000 else 7
    circle = {"kind": "circular", "radius": highs_compare.R, "voussoirs": n}
    value, peer = highs_compare.median(lambda: highs_compare.highs_dead(n, 1.0747), runs)
    answer, mine = ours("/arch/dead-load", {"geometry": dict(circle, thickness=1.0747), "include": []},
                        runs, lambda a: a["solver"]["time_ms"])
    assert abs(answer["dead_load_factor"] - value) <= 1e-6, (answer["dead_load_factor"], value)
    print(f"| arch dead load, N = {n}, λ₀ = {value:.6f} | HiGHS | {peer:.1f} ms | {mine:.2f} ms | {peer / mine:.0f}× |")
    value, peer = highs_compare.median(lambda: highs_compare.highs_live(n, 1.5), runs)
    answer, mine = ours("/arch/live-load", {"geometry": dict(circle, thickness=1.5), "include": [],
                                            "loads": [{"block": n // 4 + 1, "fy": -1.0}]},
                        runs, lambda a: a["solver"]["time_ms"])
    assert abs(answer["load_factor"] - value) <= 1e-6 * value, (answer["load_factor"], value)
    print(f"| arch live load, N = {n}, λ = {value:.4f} | HiGHS | {peer:.1f} ms | {mine:.2f} ms | {peer / mine:.0f}× |")

peer, least, theirs = pyslope_compare.search()
dry = {"slope": {"height": 30.48, "length": 60.96}, "slices": 50, "include": [],
       "soil": {"unit_weight": 10, "cohesion": 6.096, "friction_angle_deg": 40},
       "search": {"nx": 50, "ny": 50}}
answer, mine = ours("/slope/spencer", dry, 15, lambda a: a["solve_time_ms"])
circles = answer["search"]["evaluations"]
print(f"| dry 2:1 embankment, critical circle (PySlope: {theirs} circles, Bishop, F {least:.4f}; "
      f"thrustline: {circles} circles, Spencer, F {answer['factor_of_safety']:.4f}, Bishop "
      f"{answer['bishop_factor_of_safety']:.4f} there) | PySlope | {peer:.0f} ms | {mine:.2f} ms | "
      f"{peer / mine:.0f}× |")
# PySlope runs on one core; thrustline's search on every core of the machine it serves from.
cores = os.cpu_count() or 1
print(f"| the same per circle and core ({cores} cores here) | PySlope | {peer / theirs * 1e3:.0f} µs | "
      f"{mine * cores / circles * 1e3:.2f} µs | {(peer / theirs) / (mine * cores / circles):.0f}× |")
