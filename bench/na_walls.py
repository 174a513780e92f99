"""The non-associative iteration's cost and outcome on 108 walls, panels and arches, against one
or more running thrustline services (compare builds side by side): per request the status, λ
and the programmes solved, then per service the total and median programmes, how many took more
than 10, how many did not settle; and the requests whose status or λ (1e-6) differ.

Usage: python3 bench/na_walls.py BASE_URL[,BASE_URL...] [NAME_FILTER] [RELAXATION]
       (e.g. http://127.0.0.1:8080,http://127.0.0.1:8081 "" anderson: every request with
       "friction_relaxation": "anderson"; the default is the service's, the paper's)
"""
import itertools, json, sys, urllib.request

bases = sys.argv[1].split(",") if len(sys.argv) > 1 else ["http://127.0.0.1:8080"]
only = sys.argv[2] if len(sys.argv) > 2 else ""
relaxation = sys.argv[3] if len(sys.argv) > 3 else None

def post(base, path, body):
    req = urllib.request.Request(base + path, data=json.dumps(body).encode(), headers={"content-type": "application/json"})
    with urllib.request.urlopen(req, timeout=300) as r:
        return json.load(r)

def rect(x0, y0, x1, y1):
    return [[x0, y0], [x1, y0], [x1, y1], [x0, y1]]

def assembly(blocks, ground_right, mu, loads):
    return {"geometry": {"kind": "assembly", "blocks": [{"polygon": b} for b in blocks],
                         "supports": [{"polygon": rect(-2, -1, ground_right, 0)}]},
            "friction_coefficient": mu, "friction": "non_associative", "loads": loads}

cases = []
# Two leaves w × H under a cap 2w × 0.5, pushed at the cap's top-left corner or its mid-height.
for H, mu, w, at in itertools.product((0.5, 1, 2, 3), (0.3, 0.5, 0.7, 0.9), (0.3, 0.5), ("top", "mid")):
    blocks = [rect(0, 0, w, H), rect(w, 0, 2 * w, H), rect(0, H, 2 * w, H + 0.5)]
    y = H + 0.5 if at == "top" else H + 0.25
    cases.append((f"leaves H={H} mu={mu} w={w} {at}", assembly(blocks, 3, mu, [{"block": 3, "x": 0, "y": y, "fx": 1}])))
# Three leaves 0.4 wide under a cap.
for H, mu in itertools.product((1, 2), (0.4, 0.6)):
    blocks = [rect(i * 0.4, 0, (i + 1) * 0.4, H) for i in range(3)] + [rect(0, H, 1.2, H + 0.4)]
    cases.append((f"3 leaves H={H} mu={mu}", assembly(blocks, 3, mu, [{"block": 4, "x": 0, "y": H + 0.4, "fx": 1}])))
# Running-bond panels of 1 × 0.5 bricks, each brick (or the top course's) pushed by its weight.
for courses, bricks, mu, top in itertools.product((3, 4, 6), (3, 4), (0.4, 0.6, 0.8), (False, True)):
    blocks, loads = [], []
    for c in range(courses):
        xs = [0.0] + [i - 0.5 for i in range(1, bricks + 1)] + [bricks] if c % 2 else list(range(bricks + 1))
        blocks += [rect(a, c * 0.5, b, c * 0.5 + 0.5) for a, b in zip(xs, xs[1:])]
    for i, p in enumerate(blocks):
        if not top or p[0][1] >= (courses - 1) * 0.5:
            loads.append({"block": i + 1, "x": (p[0][0] + p[1][0]) / 2, "y": p[0][1] + 0.25, "fx": (p[1][0] - p[0][0]) * 0.5})
    cases.append((f"panel {courses}x{bricks} mu={mu} top={top}", assembly(blocks, bricks + 2, mu, loads)))
# Arches R = 10, D = 1.5 with a point load.
for n, mu, blk in ((20, 0.4, 6), (27, 0.3, 5), (27, 0.5, 8), (40, 0.35, 12)):
    cases.append((f"arch {n} mu={mu} b{blk}", {"geometry": {"kind": "circular", "radius": 10, "thickness": 1.5, "voussoirs": n},
                                               "friction_coefficient": mu, "friction": "non_associative", "loads": [{"block": blk, "fy": -1}]}))

counts = {b: [] for b in bases}
unsettled = {b: 0 for b in bases}
differ = []
for name, body in cases:
    if only not in name:
        continue
    if relaxation:
        body = dict(body, friction_relaxation=relaxation)
    row, outcomes = [], []
    for b in bases:
        d = post(b, "/arch/live-load", body)
        lp, status, lam = d["solver"]["programmes"], d["solver"]["status"], d.get("load_factor")
        counts[b].append(lp)
        unsettled[b] += status == "not_settled"
        outcomes.append((status, lam))
        row.append(f"{status:22s} {'-' if lam is None else f'{lam:.10f}':>13s} {lp:3d} LPs")
    s0, l0 = outcomes[0]
    if any(s != s0 or (l is None) != (l0 is None) or (l is not None and abs(l - l0) > 1e-6 * max(1, abs(l0))) for s, l in outcomes):
        differ.append(name)
    print(f"{name:34s} " + " | ".join(row))
for b in bases:
    c = sorted(counts[b])
    if c:
        print(f"{b}: {len(c)} requests, {sum(c)} programmes, median {c[len(c) // 2]}, max {c[-1]}, "
              f"more than 10: {sum(x > 10 for x in c)}, not settled: {unsettled[b]}")
if len(bases) > 1:
    print(f"status or λ differ on {len(differ)}: {differ}")
