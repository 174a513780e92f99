#!/usr/bin/env python3
"""Non-circular searches on published benchmark slopes: F against the published minima, and F
against time (the search's own path, and F for given time budgets).

    python3 bench/noncircular.py http://127.0.0.1:8093

Problems (geometry from the papers, as tabulated in McMaster's slope stability case study by
Karchewski and Frankis): Yamagami & Ueta (1988); Zolfaghari et al. (2005) with its weak layer;
Cheng et al. (2007) examples 3 (weak layer) and 4 (a 5 cm seam); Pham & Fredlund (2003) two
layers with water, and with a weak layer, water and ponding; Fredlund & Krahn (1977) with the
thin weak layer and piezometric line. Pham & Fredlund's F come from finite-element stresses
(dynamic programming), not from limit equilibrium; Fredlund & Krahn's is for one given surface.
"""
import json
import sys
import time
import urllib.request

URL = sys.argv[1] if len(sys.argv) > 1 else "http://127.0.0.1:8080"


def section(layers, piez=None, gw=9.81):
    out = {"ground": layers[0][1], "layers": []}
    for i, ((phi, c, g), top) in enumerate(layers):
        out["layers"].append({"top": None if i == 0 else top,
                              "soil": {"unit_weight": g, "cohesion": c, "friction_angle_deg": phi}})
    if piez:
        out["piezometric_line"] = piez
        out["water_unit_weight"] = gw
    return out


def zolfaghari(ground, l2, l3, l4):
    return section([((20, 15, 19), ground), ((21, 17, 19), l2), ((10, 5, 19), l3), ((28, 35, 19), l4)])


CASES = [
    ("Yamagami & Ueta", "Greco 1.327, Cheng 1.325, Li 1.327",
     section([((10, 9.8, 17.64), [[0, 5], [5, 5], [15, 10], [25, 10]])])),
    ("Zolfaghari et al.", "Cheng 1.101, Li 1.113",
     zolfaghari([[10, 50], [15, 50], [19, 48], [30.5, 42.25], [32, 41.5], [35, 41.5]],
                [[10, 48.5], [19, 48], [32, 41.5], [35, 41.5]],
                [[10, 46.7], [30.5, 42.25], [32, 41.5], [35, 41.5]],
                [[10, 46.2], [32, 41.5], [35, 41.5]])),
    ("Cheng et al. ex. 3", "Cheng 1.349, Li 1.335",
     zolfaghari([[10, 50], [15, 50], [19, 48], [25, 45], [27, 44], [32, 41.5], [40, 41.5]],
                [[10, 48.1], [19, 48], [32, 41.5], [40, 41.5]],
                [[10, 45], [25, 45], [32, 41.5], [40, 41.5]],
                [[10, 44], [27, 44], [32, 41.5], [40, 41.5]])),
    ("Cheng et al. ex. 4 (seam)", "Cheng 1.184, Li 1.197",
     zolfaghari([[10, 50], [15, 50], [19, 48], [31.9, 41.55], [32, 41.5], [35, 41.5]],
                [[10, 48.5], [19, 48], [32, 41.5], [35, 41.5]],
                [[10, 46.25], [31.9, 41.55], [32, 41.5], [35, 41.5]],
                [[10, 46.2], [32, 41.5], [35, 41.5]])),
    ("Pham & Fredlund, water", "Pham 1.413 (FE), Li 1.408",
     section([((20, 5, 15), [[0, 25], [20, 25], [30, 20], [40, 15], [70, 15]]),
              ((25, 10, 18), [[0, 20], [30, 20], [40, 15], [70, 15]])],
             [[0, 22], [10.87, 21.28], [21.14, 19.68], [31.21, 17.17], [38.69, 14.56], [40, 14], [70, 14]], 9.8)),
    ("Pham & Fredlund, weak layer", "Pham 1.000 (FE), Li 1.017",
     section([((30, 20, 15), [[0, 27], [20, 27], [44, 15], [70, 15]]),
              ((10, 0, 18), [[0, 13], [70, 13]]),
              ((30, 100, 20), [[0, 12], [70, 12]])],
             [[0, 23], [14, 22], [24, 21], [40, 17], [70, 17]], 9.8)),
    ("Fredlund & Krahn, weak layer", "1.245 (their surface)",
     section([((20, 28.74, 18.852), [[0, 18.288], [18.288, 18.288], [42.672, 6.096], [48.768, 6.096]]),
              ((10, 0, 18.852), [[0, 5.129048276], [48.768, 5.129048276]]),
              ((20, 28.74, 18.852), [[0, 4.834758621], [48.768, 4.834758621]]),
              ((50, 479, 18.852), [[0, 0], [48.768, 0]])],
             [[0, 12.192], [42.672, 6.096], [48.768, 6.096]], 9.80304)),
]


def post(body):
    req = urllib.request.Request(URL + "/slope/spencer", json.dumps(body).encode(),
                                 {"content-type": "application/json"})
    start = time.perf_counter()
    with urllib.request.urlopen(req, timeout=300) as r:
        answer = json.loads(r.read())
    return answer, time.perf_counter() - start


def main():
    print("| problem | published | circle | non-circular | request (s) | within 0.5 % at (ms) |")
    print("|---|---|---|---|---|---|")
    for name, published, sec in CASES:
        circle, _ = post({"section": sec, "search": {}, "slices": 50})
        answer, seconds = post({"section": sec, "search": {"shape": "noncircular"}, "slices": 50})
        f = answer["factor_of_safety"]
        path, ms = answer["search"]["path"], answer["search"]["path_ms"]
        near = next(t for p, t in zip(path, ms) if p <= 1.005 * f)
        print(f"| {name} | {published} | {circle['factor_of_safety']:.4f} | {f:.4f} | "
              f"{seconds:.2f} | {near:.0f} |")
    print()
    budgets = [25, 50, 100, 200, 400, 800, 1600]
    print("F against `time_budget_ms` (the polyline search's budget, after the circle search):")
    print()
    print("| problem | " + " | ".join(f"{b} ms" for b in budgets) + " |")
    print("|---|" + "---|" * len(budgets))
    for name, _, sec in CASES[1:4]:
        row = []
        for b in budgets:
            answer, _ = post({"section": sec, "slices": 50,
                              "search": {"shape": "noncircular", "time_budget_ms": b}})
            row.append(f"{answer['factor_of_safety']:.4f}")
        print(f"| {name} | " + " | ".join(row) + " |")


if __name__ == "__main__":
    main()
