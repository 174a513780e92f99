"""The same arch limit-analysis LPs solved by scipy's HiGHS (the peer an engineer would use),
side by side with thrustline: an independent implementation of Livesley's assembly formulation
(H r + λ₀w + λp = 0, q, s ≥ 0 at every joint of a semicircle of curved voussoirs), timed, and
compared with the answers and solve times of a running thrustline.

Usage: python3 bench/highs_compare.py [BASE_URL]   (default http://127.0.0.1:8080; installs
numpy and scipy from PyPI if missing; start `thrustline serve` first)
"""
import importlib
import json
import math
import statistics
import subprocess
import sys
import time
import urllib.request

for module in ("numpy", "scipy"):
    try:
        importlib.import_module(module)
    except ImportError:
        subprocess.check_call([sys.executable, "-m", "pip", "install", "-q", module])

import numpy as np  # noqa: E402
from scipy.optimize import linprog  # noqa: E402
from scipy.sparse import coo_matrix  # noqa: E402

BASE = sys.argv[1] if len(sys.argv) > 1 and __name__ == "__main__" else "http://127.0.0.1:8080"
R = 10.0


def arch(n, d):
    """Blocks (area, centroid) and joints (P_s, P_q, normal, tangent) of the semicircle."""
    ri, re = R - d / 2, R + d / 2
    phis = [math.pi * k / n for k in range(n + 1)]
    half = math.pi / (2 * n)
    rho = 2 / 3 * (re**3 - ri**3) / (re**2 - ri**2) * math.sin(half) / half
    blocks = []
    for b in range(n):
        mid = (phis[b] + phis[b + 1]) / 2
        blocks.append((half * (re * re - ri * ri), (rho * math.cos(mid), rho * math.sin(mid))))
    joints = []
    for phi in phis:
        c, s = math.cos(phi), math.sin(phi)
        joints.append(((ri * c, ri * s), (re * c, re * s), (-s, c), (c, s)))
    return blocks, joints


def equilibrium(blocks, joints):
    """H (3 rows per block: x, y, moment about the centroid; 3 columns per joint: q, s, t)."""
    rows, cols, vals = [], [], []
    n = len(blocks)
    cross = lambda a, b: a[0] * b[1] - a[1] * b[0]
    for k, (ps, pq, nu, tau) in enumerate(joints):
        for b, sign in ((k, 1.0), (k - 1, -1.0)):
            if not 0 <= b < n:
                continue
            g = blocks[b][1]
            aq = (pq[0] - g[0], pq[1] - g[1])
            as_ = (ps[0] - g[0], ps[1] - g[1])
            for j, (f, arm) in enumerate(((nu, aq), (nu, as_), (tau, as_))):
                rows += [3 * b, 3 * b + 1, 3 * b + 2]
                cols += [3 * k + j] * 3
                vals += [sign * f[0], sign * f[1], sign * cross(arm, f)]
    return coo_matrix((vals, (rows, cols)), shape=(3 * n, 3 * (n + 1))).tocsc()


def bounds(n_joints, extra):
    b = []
    for _ in range(n_joints):
        b += [(0, None), (0, None), (None, None)]
    return b + [extra]


def highs_dead(n, d):
    blocks, joints = arch(n, d)
    h = equilibrium(blocks, joints)
    w = np.zeros(3 * n)
    for b, (area, _) in enumerate(blocks):
        w[3 * b + 1] = -area
    from scipy.sparse import hstack
    a_eq = hstack([h, coo_matrix(w.reshape(-1, 1))]).tocsc()
    c = np.zeros(a_eq.shape[1])
    c[-1] = -1.0  # maximise λ₀
    start = time.perf_counter()
    result = linprog(c, A_eq=a_eq, b_eq=np.zeros(3 * n), bounds=bounds(n + 1, (0, 1)), method="highs")
    return -result.fun, (time.perf_counter() - start) * 1e3


def highs_live(n, d):
    blocks, joints = arch(n, d)
    h = equilibrium(blocks, joints)
    w = np.zeros(3 * n)
    for b, (area, _) in enumerate(blocks):
        w[3 * b + 1] = -area
    p = np.zeros(3 * n)
    block = n // 4
    p[3 * block + 1] = -1.0  # unit load at the centroid of block n/4 + 1 (1-based)
    from scipy.sparse import hstack
    a_eq = hstack([h, coo_matrix(p.reshape(-1, 1))]).tocsc()
    c = np.zeros(a_eq.shape[1])
    c[-1] = -1.0
    start = time.perf_counter()
    result = linprog(c, A_eq=a_eq, b_eq=-w, bounds=bounds(n + 1, (0, None)), method="highs")
    return -result.fun, (time.perf_counter() - start) * 1e3


def thrustline(path, body):
    request = urllib.request.Request(BASE + path, data=json.dumps(body).encode(), headers={"content-type": "application/json"})
    with urllib.request.urlopen(request) as response:
        return json.load(response)


def median(f, runs):
    values = [f() for _ in range(runs)]
    return values[-1][0], statistics.median(v[1] for v in values)


def main():
    print("| problem | N | HiGHS answer | HiGHS time | thrustline answer | thrustline solve time | ratio |")
    print("|---|---|---|---|---|---|---|")
    for n in (100, 1800, 10000):
        runs = 3 if n >= 10000 else 7
        for d in (1.0747, 1.0748):
            value, highs_ms = median(lambda: highs_dead(n, d), runs)
            body = {"geometry": {"kind": "circular", "radius": R, "thickness": d, "voussoirs": n}}
            answers = [thrustline("/arch/dead-load", body) for _ in range(runs)]
            ours = statistics.median(a["solver"]["time_ms"] for a in answers)
            print(f"| dead load, D = {d} | {n} | λ₀ = {value:.6f} | {highs_ms:.1f} ms | λ₀ = {answers[-1]['dead_load_factor']} | {ours:.2f} ms | {highs_ms / ours:.0f}× |")
        value, highs_ms = median(lambda: highs_live(n, 1.5), runs)
        body = {"geometry": {"kind": "circular", "radius": R, "thickness": 1.5, "voussoirs": n}, "loads": [{"block": n // 4 + 1, "fy": -1.0}]}
        answers = [thrustline("/arch/live-load", body) for _ in range(runs)]
        ours = statistics.median(a["solver"]["time_ms"] for a in answers)
        print(f"| live load, D = 1.5 | {n} | λ = {value:.6f} | {highs_ms:.1f} ms | λ = {answers[-1]['load_factor']:.6f} | {ours:.2f} ms | {highs_ms / ours:.0f}× |")


if __name__ == "__main__":
    main()
