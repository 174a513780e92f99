"""Random slope problems answered by two running thrustline servers, compared: how far a change
moves Spencer's F, and whether it moves only answers the service already flags.

Usage: python3 bench/differential.py OLD_URL NEW_URL [SEED] [COUNT]

Each problem is a simple slope (height 3-40, face 0.3-4 times as long, c' 0 or 1-40,
phi' 0-40 degrees, r_u in 40 % of them, k_h in 30 %) with a given circle or a 15 x 15 search,
20-50 slices. Prints the number compared, any change of HTTP status or answer status, how many F
moved by more than 1e-12 relative and how many of those the answers flag (warnings
`unsolved_near_minimum` / `unsolved_below_minimum`: circles without a root at or next to the
minimum, where whether a circle has a root can turn on rounding), the largest change among
unflagged answers, and the largest changes. Exits 1 on a status change or an unflagged change
beyond 1e-12.
"""
import json, random, sys, urllib.error, urllib.request


def post(base, body):
    req = urllib.request.Request(base + "/slope/spencer", data=json.dumps(body).encode(),
                                 headers={"content-type": "application/json"})
    try:
        with urllib.request.urlopen(req, timeout=120) as r:
            return r.status, json.load(r)
    except urllib.error.HTTPError as e:
        return e.code, json.loads(e.read() or b"{}")


def problem(rng):
    h = rng.uniform(3, 40)
    soil = {"unit_weight": rng.uniform(15, 22), "cohesion": rng.choice([0, rng.uniform(1, 40)]),
            "friction_angle_deg": rng.uniform(0, 40)}
    if rng.random() < 0.4:
        soil["pore_pressure_ratio"] = rng.uniform(0, 0.6)
    length = h * rng.uniform(0.3, 4)
    body = {"slope": {"height": h, "length": length}, "soil": soil,
            "slices": rng.choice([20, 30, 50]), "include": []}
    if rng.random() < 0.5:
        body["search"] = {"nx": 15, "ny": 15}
    else:
        body["circle"] = {"x": rng.uniform(-length, length), "y": rng.uniform(0.6 * h, 3 * h)}
    if rng.random() < 0.3:
        body["seismic"] = {"kh": rng.uniform(0, 0.2), "kv": 0.0}
    return body


def main():
    old, new = sys.argv[1], sys.argv[2]
    rng = random.Random(int(sys.argv[3]) if len(sys.argv) > 3 else 1)
    count = int(sys.argv[4]) if len(sys.argv) > 4 else 200
    moved, changed = [], []
    compared = 0
    for k in range(count):
        body = problem(rng)
        (sa, a), (sb, b) = post(old, body), post(new, body)
        if sa != sb or a.get("status") != b.get("status"):
            changed.append((k, sa, sb, a.get("status"), b.get("status"), json.dumps(body)))
            continue
        fa, fb = a.get("factor_of_safety"), b.get("factor_of_safety")
        if isinstance(fa, float) and isinstance(fb, float):
            compared += 1
            flags = sorted({w["code"] for w in a.get("warnings", []) + b.get("warnings", [])
                            if w["code"].startswith("unsolved")})
            moved.append((abs(fa - fb) / abs(fa), k, fa, fb, ",".join(flags) or "-"))
    moved.sort(reverse=True)
    beyond = [m for m in moved if m[0] > 1e-12]
    unflagged = max((m[0] for m in moved if m[4] == "-"), default=0.0)
    print(f"{count} problems, {compared} F compared, {len(changed)} status changes")
    print(f"F moved beyond 1e-12: {len(beyond)}, flagged: {sum(m[4] != '-' for m in beyond)}; "
          f"largest unflagged change {unflagged:.1e}")
    for m in moved[:6]:
        print("  %.1e  problem %d: F %r -> %r  %s" % m)
    for c in changed:
        print("  status change: problem %d: %s %s -> %s %s: %s" % c)
    failed = changed or any(m[4] == "-" for m in beyond)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
