"""Golden comparison: the same requests (every route, every option family) answered by two
running thrustline servers, compared number for number. Wall times are left out; every other
number must agree within --rtol (default 0: bit for bit, as JSON prints it).

Usage: python3 bench/golden.py OLD_URL NEW_URL [--rtol 1e-12] [--report]
Prints one line per request and exits 1 on any difference. With --report it measures the
differences instead: for each field (list indices left out: every slice's `force` is one field),
the largest |old - new| over the largest |value| of that field in the answer, field by field
across all requests, largest first (a change at rounding shows ~1e-16..1e-14 on well-conditioned
fields; a difference of two close numbers, or a quotient by a force near zero, shows more).
"""
import re
import json, math, sys, urllib.error, urllib.request

TIMES = {"solve_time_ms", "time_ms", "time_per_position_ms", "first_position_ms", "path_ms"}

circle = lambda **k: dict({"kind": "circular", "radius": 10.0, "thickness": 1.0, "voussoirs": 40}, **k)
sp = {"slope": {"height": 30.48, "length": 60.96},
      "soil": {"unit_weight": 10.0, "cohesion": 6.096, "friction_angle_deg": 40.0, "pore_pressure_ratio": 0.5}}
layered = {"section": {"ground": [[-20, 0], [0, 0], [20, 10], [40, 10]],
    "layers": [{"top": None, "soil": {"unit_weight": 19, "cohesion": 10, "friction_angle_deg": 28}},
               {"top": [[-20, -3], [40, -3]], "soil": {"unit_weight": 20, "cohesion": 0, "friction_angle_deg": 35}}],
    "bedrock": [[-20, -12], [40, -12]], "piezometric_line": [[-20, 1], [10, 3], [40, 6]],
    "surcharges": [{"x_start": 25, "x_end": 35, "pressure": 20}], "line_loads": [{"x": 30, "fx": 0, "fy": -50}],
    "tension_crack": {"depth": 2.5, "water_depth": 2.5}}}
fk = {"section": {"ground": [[0, 60], [60, 60], [140, 20], [180, 20]],
                  "layers": [{"top": None, "soil": {"unit_weight": 120, "cohesion": 600, "friction_angle_deg": 20}}]}}
weak = {"section": {"ground": [[0, 0], [10, 0], [30, 10], [50, 10]],
    "layers": [{"top": None, "soil": {"unit_weight": 20, "cohesion": 10, "friction_angle_deg": 30}},
               {"top": [[0, 1], [50, 1]], "soil": {"unit_weight": 20, "cohesion": 1, "friction_angle_deg": 8}},
               {"top": [[0, 0.5], [50, 0.5]], "soil": {"unit_weight": 20, "cohesion": 10, "friction_angle_deg": 30}}]}}
wall = {"geometry": {"kind": "assembly",
    "blocks": [{"polygon": [[0, 0], [0.5, 0], [0.5, 2], [0, 2]]}, {"polygon": [[0.5, 0], [1, 0], [1, 2], [0.5, 2]]},
               {"polygon": [[0, 2], [1, 2], [1, 2.5], [0, 2.5]]}],
    "supports": [{"polygon": [[-2, -1], [3, -1], [3, 0], [-2, 0]]}]},
    "friction_coefficient": 0.5, "loads": [{"block": 3, "x": 0, "y": 2.5, "fx": 1}]}
fill = {"unit_weight": 1.8, "surface": 11.5, "dispersal_angle_deg": 30.0}

REQUESTS = [
    ("/arch/dead-load", {"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0748, "voussoirs": 1800}}),
    ("/arch/dead-load", {"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0747, "voussoirs": 1800}}),
    ("/arch/dead-load", {"geometry": circle(thickness=1.0747, voussoir="quadrilateral"), "formulation": "assembly"}),
    ("/arch/dead-load", {"geometry": circle(rings=2), "ring_friction_coefficient": 0.6}),
    ("/arch/dead-load", {"geometry": circle(thickness=0.6, rings=2), "ring_friction_coefficient": 0.0}),
    ("/arch/dead-load", {"geometry": circle(), "compressive_strength": 20.0}),
    ("/arch/dead-load", {"geometry": circle(), "fill": fill}),
    ("/arch/live-load", {"geometry": circle(thickness=1.5, voussoirs=100), "loads": [{"block": 26, "fy": -1.0}]}),
    ("/arch/live-load", {"geometry": circle(thickness=2.0, voussoirs=20), "friction_coefficient": 0.4,
                         "loads": [{"block": 6, "fy": -1}]}),
    ("/arch/live-load", wall),
    ("/arch/live-load", dict(wall, friction="non_associative")),
    ("/arch/live-load", dict(wall, friction="non_associative", friction_relaxation="anderson")),
    ("/arch/live-load", {"geometry": circle(voussoirs=100), "fill": fill,
                         "road_loads": [{"x": -4.0, "fy": -10.0, "length": 0.3}]}),
    ("/arch/live-load", {"geometry": circle(voussoirs=100), "fill": dict(fill, passive={"friction_angle_deg": 30, "mobilisation": 0.5}),
                         "road_loads": [{"x": -4.0, "fy": -10.0, "length": 0.3}]}),
    ("/arch/live-load", {"geometry": circle(voussoirs=100), "fill": {"unit_weight": 1.8, "surface": 11.5},
                         "rolling": {"axles": [{"offset": 0.0, "fy": -10.0}, {"offset": 1.8, "fy": -10.0}],
                                     "x_start": -12.0, "x_end": 10.0, "positions": 101}}),
    ("/arch/live-load", {"geometry": circle(voussoirs=40), "fill": {"unit_weight": 1.8, "surface": 11.5}, "friction_coefficient": 0.5,
                         "rolling": {"axles": [{"offset": 0.0, "fy": -10.0}], "x_start": -9.0, "x_end": 9.0, "positions": 19}}),
    ("/arch/live-load", {"geometry": circle(voussoirs=100), "fill": {"unit_weight": 1.8, "surface": 11.5},
                         "rolling": {"axles": [{"offset": 0.0, "fy": -10.0}, {"offset": 1.8, "fy": -10.0}],
                                     "x_start": -12.0, "x_end": 10.0, "positions": 101, "refine_critical": True}}),
    ("/arch/live-load", {"geometry": circle(thickness=1.5, voussoirs=100, rings=2), "compressive_strength": 50,
                         "loads": [{"block": 26, "fy": -1}]}),
    ("/arch/live-load", {"geometry": circle(voussoirs=40, rings=2), "loads": [{"block": 10, "fy": -1}]}),
    ("/arch/live-load", {"geometry": circle(thickness=1.5, voussoirs=30, spans=3, pier_width=4.0, pier_height=4.0),
                         "loads": [{"block": 8, "fy": -1}]}),
    ("/arch/live-load", {"geometry": circle(voussoirs=60), "compressive_strength": 50.0,
                         "loads": [{"block": 16, "fy": -1}]}),
    ("/arch/minimum-thickness", {"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0, "voussoirs": 1800}}),
    ("/arch/minimum-thickness", {"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0, "voussoirs": 100,
                                              "left_base_angle_deg": 20, "right_base_angle_deg": 20}}),
    ("/slope/spencer", dict(sp, circle={"x": 9.63168, "y": 63.76416}, slices=100)),
    ("/slope/spencer", dict(sp, circle={"x": 9.63168, "y": 63.76416}, slices=100, curves=True,
                            methods=["morgenstern_price", "bishop", "janbu", "ordinary"])),
    ("/slope/spencer", dict(sp, circle={"x": 9.63168, "y": 63.76416}, slices=10, slice_tolerance=1e-6)),
    ("/slope/spencer", dict(sp, circle={"x": 9.63168, "y": 63.76416, "lower_end_factor": 0.2}, slices=50,
                            seismic={"kh": 0.1, "kv": 0.05}, external_loads=[{"slice": 3, "fx": 1, "fy": -5, "moment": 2}])),
    ("/slope/spencer", dict(sp, circle={"centre": [20, 70], "radius": 70}, slices=100)),
    ("/slope/spencer", dict(sp, search={}, slices=50)),
    ("/slope/spencer", dict(sp, search={"x_min": 0, "x_max": 30, "y_min": 40, "y_max": 90, "nx": 11, "ny": 11}, slices=50)),
    ("/slope/spencer", dict(sp, search={"lower_end_factor_max": 0.5}, slices=30)),
    ("/slope/spencer", dict(fk, circle={"centre": [120, 90], "radius": 80}, slices=100,
                            methods=["morgenstern_price", "bishop", "janbu", "ordinary"])),
    ("/slope/spencer", dict(fk, surface=[[40, 62], [70, 38], [130, 22], [165, 21]], slices=100, moment_centre=[120, 90],
                            methods=["bishop", "morgenstern_price"], interslice_function=[[0, 0.5], [0.5, 1], [1, 0.5]])),
    ("/slope/spencer", dict(layered, circle={"centre": [12, 28], "radius": 26}, slices=100, negative_effective_stress="drop_friction")),
    ("/slope/spencer", dict(layered, search={}, slices=40)),
    ("/slope/spencer", dict(fk, search={"nx": 11, "ny": 11}, slices=40)),
    ("/slope/spencer", dict(weak, search={"shape": "noncircular", "time_budget_ms": 60000}, slices=30)),
]


def post(base, path, body, accept=None):
    headers = {"content-type": "application/json"}
    req = urllib.request.Request(base + path, data=json.dumps(body).encode(), headers=headers)
    try:
        with urllib.request.urlopen(req, timeout=300) as r:
            return r.status, r.read()
    except urllib.error.HTTPError as e:
        return e.code, e.read()


def differences(a, b, rtol, where=""):
    if isinstance(a, dict) and isinstance(b, dict):
        out = []
        for k in sorted(set(a) | set(b)):
            if k in TIMES:
                continue
            if k not in a or k not in b:
                out.append(f"{where}.{k}: only in {'new' if k in b else 'old'}")
            else:
                out += differences(a[k], b[k], rtol, f"{where}.{k}")
        return out
    if isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            return [f"{where}: {len(a)} vs {len(b)} items"]
        return [d for i, (x, y) in enumerate(zip(a, b)) for d in differences(x, y, rtol, f"{where}[{i}]")]
    if isinstance(a, float) and isinstance(b, float) and a != b:
        if rtol and math.isfinite(a) and abs(a - b) <= rtol * max(abs(a), abs(b)):
            return []
        return [f"{where}: {a!r} vs {b!r}"]
    return [] if a == b else [f"{where}: {a!r} vs {b!r}"]


def fields(value, where="", out=None):
    """Every number in an answer, by field (list indices left out)."""
    out = {} if out is None else out
    if isinstance(value, dict):
        for k, v in value.items():
            if k not in TIMES:
                fields(v, f"{where}.{k}", out)
    elif isinstance(value, list):
        for v in value:
            fields(v, f"{where}[]", out)
    elif isinstance(value, float) and math.isfinite(value):
        out.setdefault(where, []).append(value)
    return out


def report(old, new):
    """The largest difference of each field relative to its largest value, over all requests."""
    worst = {}
    for path, body in REQUESTS:
        (sa, a), (sb, b) = post(old, path, body), post(new, path, body)
        if sa != sb:
            print(f"status {sa} vs {sb}: {path} {json.dumps(body)[:70]}")
            continue
        fa, fb = fields(json.loads(a)), fields(json.loads(b))
        for name in fa.keys() & fb.keys():
            xs, ys = fa[name], fb[name]
            if len(xs) != len(ys):
                print(f"{name}: {len(xs)} vs {len(ys)} values: {path}")
                continue
            scale = max(abs(v) for v in xs + ys)
            diff = max(abs(x - y) for x, y in zip(xs, ys))
            if scale > 0:
                field = re.sub(r"^\.", "", name)
                worst[field] = max(worst.get(field, 0.0), diff / scale)
    for field, rel in sorted(worst.items(), key=lambda kv: -kv[1]):
        print(f"{rel:9.1e}  {field}")


def main():
    old, new = sys.argv[1], sys.argv[2]
    if "--report" in sys.argv:
        report(old, new)
        return
    rtol = float(sys.argv[sys.argv.index("--rtol") + 1]) if "--rtol" in sys.argv else 0.0
    failed = 0
    for path, body in REQUESTS:
        for route in (path, path + "/svg") if path != "/arch/minimum-thickness" else (path,):
            (sa, a), (sb, b) = post(old, route, body), post(new, route, body)
            if route.endswith("/svg"):
                diff = [] if (sa, a) == (sb, b) else [f"svg differs ({len(a)} vs {len(b)} bytes)"]
            else:
                diff = [f"status {sa} vs {sb}"] if sa != sb else differences(json.loads(a), json.loads(b), rtol)
            label = f"{route} {json.dumps(body)[:70]}"
            print(("same  " if not diff else "DIFF  ") + label)
            for d in diff[:5]:
                print("      " + d)
            failed += bool(diff)
    print(f"{len(REQUESTS)} requests, {failed} answers differ")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
