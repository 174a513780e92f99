"""Soak test: mixed traffic at a fraction of measured capacity for a while, against a running
`thrustline serve` on loopback; reports statuses, latency percentiles per request kind and the
server's resident memory over time (read from /proc/PID/status).

Usage: python3 bench/soak.py URL SERVER_PID [minutes=10] [fraction=0.8]
The capacity is measured first (closed loop, 8 clients, 20 s); the soak then sends requests at
`fraction` of it with Poisson arrivals (open loop, so a slow server meets a queue, as in
production), each from a pool of 64 client threads.
"""
import json
import queue
import random
import statistics
import sys
import threading
import time
import urllib.error
import urllib.request

base = sys.argv[1]
pid = int(sys.argv[2])
minutes = float(sys.argv[3]) if len(sys.argv) > 3 else 10.0
fraction = float(sys.argv[4]) if len(sys.argv) > 4 else 0.8

soil = {"unit_weight": 10.0, "cohesion": 6.096, "friction_angle_deg": 40.0, "pore_pressure_ratio": 0.5}
slope = {"height": 30.48, "length": 60.96}
layered = {"ground": [[-20, 0], [0, 0], [20, 10], [40, 10]],
           "layers": [{"top": None, "soil": {"unit_weight": 19, "cohesion": 10, "friction_angle_deg": 28}},
                      {"top": [[-20, -3], [40, -3]], "soil": {"unit_weight": 20, "cohesion": 0, "friction_angle_deg": 35}}],
           "piezometric_line": [[-20, 1], [10, 3], [40, 6]]}
# (kind, path, body, weight)
MIX = [
    ("arch dead N=100", "/arch/dead-load", {"geometry": {"kind": "circular", "radius": 10, "thickness": 1.0748, "voussoirs": 100}}, 3),
    ("arch live N=100", "/arch/live-load", {"geometry": {"kind": "circular", "radius": 10, "thickness": 1.5, "voussoirs": 100}, "loads": [{"block": 26, "fy": -1}]}, 3),
    ("minimum thickness N=100", "/arch/minimum-thickness", {"geometry": {"kind": "circular", "radius": 10, "voussoirs": 100}}, 1),
    ("spencer circle 100", "/slope/spencer", {"slope": slope, "soil": soil, "circle": {"x": 9.63168, "y": 63.76416, "lower_end_factor": 0.0}, "slices": 100}, 4),
    ("spencer search 21x21", "/slope/spencer", {"slope": slope, "soil": soil, "search": {}, "slices": 50}, 1),
    ("section circle 100", "/slope/spencer", {"section": layered, "circle": {"centre": [12, 28], "radius": 26}, "slices": 100}, 3),
    ("bad input", "/slope/spencer", {"slope": {"height": -1, "length": 2}, "soil": soil, "circle": {"x": 1, "y": 5}}, 1),
    ("slope svg", "/slope/spencer/svg", {"slope": slope, "soil": soil, "circle": {"x": 9.63168, "y": 63.76416, "lower_end_factor": 0.0}, "slices": 50}, 1),
]
weights = [m[3] for m in MIX]


def send(kind, path, body):
    data = json.dumps(body).encode()
    request = urllib.request.Request(base + path, data=data, headers={"content-type": "application/json"})
    start = time.perf_counter()
    try:
        with urllib.request.urlopen(request, timeout=120) as response:
            response.read()
            status = response.status
    except urllib.error.HTTPError as error:
        error.read()
        status = error.code
    except Exception:  # connection errors count as such
        status = 0
    return status, time.perf_counter() - start


def rss_kib():
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    return 0


def capacity(seconds=20.0, clients=8):
    done = []
    stop = time.perf_counter() + seconds
    lock = threading.Lock()

    def client():
        while time.perf_counter() < stop:
            kind, path, body, _ = random.choices(MIX, weights)[0]
            s, t = send(kind, path, body)
            with lock:
                done.append((kind, s, t))

    threads = [threading.Thread(target=client) for _ in range(clients)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    return len(done) / seconds


random.seed(1)
rate_max = capacity()
rate = fraction * rate_max
print(f"capacity {rate_max:.1f} req/s (8 closed-loop clients, 20 s); soaking at {rate:.1f} req/s for {minutes} min")
results = []
lock = threading.Lock()
jobs = queue.Queue()


def worker():
    while True:
        job = jobs.get()
        if job is None:
            return
        kind, path, body = job
        s, t = send(kind, path, body)
        with lock:
            results.append((kind, s, t))


threads = [threading.Thread(target=worker, daemon=True) for _ in range(64)]
for t in threads:
    t.start()
rss = [(0.0, rss_kib())]
start = time.perf_counter()
end = start + 60.0 * minutes
next_sample = start + 5.0
t = start
while t < end:
    t += random.expovariate(rate)
    now = time.perf_counter()
    if t > now:
        time.sleep(t - now)
    kind, path, body, _ = random.choices(MIX, weights)[0]
    jobs.put((kind, path, body))
    if time.perf_counter() >= next_sample:
        rss.append((time.perf_counter() - start, rss_kib()))
        next_sample += 5.0
for _ in threads:
    jobs.put(None)
for th in threads:
    th.join()
rss.append((time.perf_counter() - start, rss_kib()))

statuses = {}
for _, s, _ in results:
    statuses[s] = statuses.get(s, 0) + 1
print(f"{len(results)} requests in {time.perf_counter() - start:.0f} s; statuses {dict(sorted(statuses.items()))}")
print("| request | n | p50 | p99 | max |")
print("|---|---|---|---|---|")
for kind, *_ in MIX:
    times = sorted(t for k, s, t in results if k == kind)
    if not times:
        continue
    p = lambda q: times[min(len(times) - 1, int(q * len(times)))] * 1e3
    print(f"| {kind} | {len(times)} | {p(0.5):.1f} ms | {p(0.99):.1f} ms | {times[-1] * 1e3:.1f} ms |")
all_times = sorted(t for _, _, t in results)
print(f"all: p50 {all_times[len(all_times) // 2] * 1e3:.1f} ms, p99 {all_times[int(0.99 * len(all_times))] * 1e3:.1f} ms")
values = [r for _, r in rss]
print(f"RSS: start {values[0] / 1024:.1f} MiB, max {max(values) / 1024:.1f} MiB, end {values[-1] / 1024:.1f} MiB; "
      f"first minute max {max(r for s, r in rss if s <= 60) / 1024:.1f} MiB, last minute max {max(r for s, r in rss if s >= rss[-1][0] - 60) / 1024:.1f} MiB")
