"""Abuse test: the probe's heavy requests, a 150-connection mixed load, clients that go away,
trickled bodies, silent sockets and SIGTERM under load, against a `thrustline serve` this script
starts itself (default settings, loopback); reports latencies per request kind, statuses and the
server's peak resident memory (VmHWM from /proc) after each phase.

Usage: python3 bench/abuse.py PATH/TO/thrustline [seconds of mixed load = 60] [phases = all | mixed]
"""
import json
import os
import random
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time
import urllib.error
import urllib.request

binary = sys.argv[1]
seconds = float(sys.argv[2]) if len(sys.argv) > 2 else 60.0
only_mixed = len(sys.argv) > 3 and sys.argv[3] == "mixed"

soil = {"unit_weight": 10.0, "cohesion": 6.096, "friction_angle_deg": 40.0, "pore_pressure_ratio": 0.5}
slope = {"height": 30.48, "length": 60.96}
layered = {"ground": [[-20, 0], [0, 0], [20, 10], [40, 10]],
           "layers": [{"top": None, "soil": {"unit_weight": 19, "cohesion": 10, "friction_angle_deg": 28}},
                      {"top": [[-20, -3], [40, -3]], "soil": {"unit_weight": 20, "cohesion": 0, "friction_angle_deg": 35}}]}
ring = {"kind": "circular", "radius": 10, "thickness": 1.5}
# (kind, light?, path, body, weight)
MIX = [
    ("arch dead N=100", True, "/arch/dead-load", {"geometry": {**ring, "thickness": 1.0748, "voussoirs": 100}}, 3),
    ("arch live N=100", True, "/arch/live-load", {"geometry": {**ring, "voussoirs": 100}, "loads": [{"block": 26, "fy": -1}]}, 3),
    ("spencer circle 100", True, "/slope/spencer", {"slope": slope, "soil": soil, "circle": {"x": 9.63168, "y": 63.76416, "lower_end_factor": 0.0}, "slices": 100}, 4),
    ("section circle 100", True, "/slope/spencer", {"section": layered, "circle": {"centre": [12, 28], "radius": 26}, "slices": 100}, 3),
    ("bad input", True, "/slope/spencer", {"slope": {"height": -1, "length": 2}, "soil": soil, "circle": {"x": 1, "y": 5}}, 1),
    ("spencer search 21x21", False, "/slope/spencer", {"slope": slope, "soil": soil, "search": {}, "slices": 50, "include": []}, 2),
    ("minimum thickness N=100", False, "/arch/minimum-thickness", {"geometry": {"kind": "circular", "radius": 10, "voussoirs": 100}}, 1),
    ("two rings 2x300 crushing", False, "/arch/live-load", {"geometry": {**ring, "voussoirs": 300, "rings": 2}, "ring_friction_coefficient": 0.6, "loads": [{"block": 80, "fy": -1}], "compressive_strength": 50, "include": []}, 1),
    ("rolling 101 stops N=400", False, "/arch/live-load", {"geometry": {**ring, "thickness": 1.0, "voussoirs": 400}, "fill": {"unit_weight": 1.8, "surface": 11.5}, "rolling": {"axles": [{"offset": 0.0, "fy": -10.0}, {"offset": 1.8, "fy": -10.0}], "x_start": -12.0, "x_end": 10.0, "positions": 101}, "include": []}, 1),
    ("non-circular 2 s", False, "/slope/spencer", {"section": layered, "search": {"shape": "noncircular", "time_budget_ms": 2000}, "slices": 50, "include": []}, 1),
]
weights = [m[4] for m in MIX]

# The probe's heavy requests (issue 38): what each must answer.
PROBE = [
    ("ten rings of 1990, crushing, friction iteration", "/arch/live-load",
     {"geometry": {**ring, "voussoirs": 1990, "rings": 10}, "ring_friction_coefficient": 0.6, "loads": [{"block": 80, "fy": -1}],
      "compressive_strength": 50, "friction": "non_associative", "friction_coefficient": 0.6}),
    ("1001 stops of 20 axles over 10,000 voussoirs", "/arch/live-load",
     {"geometry": {**ring, "voussoirs": 10000}, "fill": {"unit_weight": 1.8, "surface": 30, "dispersal_angle_deg": 60},
      "rolling": {"axles": [{"offset": float(i), "fy": -10.0} for i in range(20)], "x_start": -30, "x_end": 10, "positions": 1001}, "include": []}),
    ("four rings of 1100 with crushing (fits)", "/arch/live-load",
     {"geometry": {**ring, "voussoirs": 1100, "rings": 4}, "ring_friction_coefficient": 0.6, "loads": [{"block": 80, "fy": -1}],
      "compressive_strength": 50, "include": []}),
    ("non-circular search, 40 vertices, 2000 slices, to the time limit", "/slope/spencer",
     {"section": layered, "search": {"shape": "noncircular", "vertices": 40, "time_budget_ms": 600000, "max_evaluations": 1000000},
      "slices": 2000, "include": []}),
]


def start_server(env_extra=None):
    port_file = os.path.join(tempfile.mkdtemp(), "port")
    env = dict(os.environ, THRUSTLINE_ADDR="127.0.0.1:0", THRUSTLINE_PORT_FILE=port_file, RUST_LOG="warn")
    env.update(env_extra or {})
    proc = subprocess.Popen([binary, "serve"], env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    for _ in range(500):
        try:
            port = int(open(port_file).read().strip())
            return proc, port
        except (OSError, ValueError):
            time.sleep(0.02)
    raise SystemExit("the server did not start")


def peak_mib(pid):
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith("VmHWM:"):
                return int(line.split()[1]) / 1024
    return 0.0


def send(port, path, body, timeout=120):
    data = json.dumps(body).encode()
    request = urllib.request.Request(f"http://127.0.0.1:{port}{path}", data=data,
                                     headers={"content-type": "application/json"})
    start = time.perf_counter()
    try:
        with urllib.request.urlopen(request, timeout=timeout) as response:
            text = response.read()
            status = response.status
    except urllib.error.HTTPError as error:
        text = error.read()
        status = error.code
    except Exception:
        text, status = b"", 0
    return status, time.perf_counter() - start, text


def percentile(times, q):
    times = sorted(times)
    return times[min(len(times) - 1, int(q * len(times)))] * 1e3 if times else float("nan")


def mixed_load(port, pid, connections, duration):
    results, lock = [], threading.Lock()
    stop = time.perf_counter() + duration
    rng = random.Random(1)

    def client(seed):
        # Each connection sends a request, waits for it, then thinks for an exponential time
        # (mean 1 s): about 150 requests/s offered, a third of them heavy — enough to keep
        # the heavy lane's workers and queue full — without the Python client's own
        # throughput setting the latency (closed loop with no pause measures the client).
        r = random.Random(seed)
        time.sleep(r.expovariate(1.0))
        while time.perf_counter() < stop:
            kind, light, path, body, _ = r.choices(MIX, weights)[0]
            status, took, _ = send(port, path, body)
            with lock:
                results.append((kind, light, status, took))
            time.sleep(r.expovariate(1.0))

    threads = [threading.Thread(target=client, args=(rng.random(),)) for _ in range(connections)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    statuses = {}
    for _, _, s, _ in results:
        statuses[s] = statuses.get(s, 0) + 1
    print(f"\n## Mixed load: {connections} connections for {duration:.0f} s, each pausing 1 s (mean) between requests\n")
    print(f"{len(results)} requests; statuses {dict(sorted(statuses.items()))}; peak RSS {peak_mib(pid):.1f} MiB\n")
    print("| request | lane | n | p50 | p99 |")
    print("|---|---|---|---|---|")
    for kind, light, *_ in MIX:
        times = [t for k, _, _, t in results if k == kind]
        print(f"| {kind} | {'light' if light else 'heavy'} | {len(times)} | {percentile(times, 0.5):.1f} ms | {percentile(times, 0.99):.1f} ms |")
    light = [t for _, l, s, t in results if l]
    print(f"\nlight requests: p50 {percentile(light, 0.5):.1f} ms, p99 {percentile(light, 0.99):.1f} ms")


def probe(port, pid):
    print("\n## The probe's heavy requests, one at a time\n")
    print("| request | status | time | peak RSS so far | answer |")
    print("|---|---|---|---|---|")
    for name, path, body in PROBE:
        status, took, text = send(port, path, body)
        detail = json.loads(text).get("detail", "") if status >= 400 and text else ""
        print(f"| {name} | {status} | {took:.2f} s | {peak_mib(pid):.0f} MiB | {detail[:90]} |")


def light_latency(port):
    _, took, _ = send(port, "/arch/dead-load", MIX[0][3])
    return took * 1e3


def running_solves(port):
    with urllib.request.urlopen(f"http://127.0.0.1:{port}/healthz", timeout=10) as r:
        return json.loads(r.read())["running_solves"]


def disconnects(port):
    print("\n## Clients that go away\n")
    body = json.dumps(PROBE[3][2]).encode()
    for _ in range(20):
        s = socket.create_connection(("127.0.0.1", port))
        s.sendall(b"POST /slope/spencer HTTP/1.1\r\nHost: x\r\ncontent-type: application/json\r\n"
                  + f"content-length: {len(body)}\r\n\r\n".encode() + body)
        time.sleep(0.05)
        s.close()
    start = time.perf_counter()
    while running_solves(port) > 0 and time.perf_counter() - start < 30:
        time.sleep(0.01)
    freed = time.perf_counter() - start
    print(f"20 one-minute searches sent and abandoned after 50 ms each: workers free {freed * 1e3:.0f} ms after the last; "
          f"a light request then takes {light_latency(port):.1f} ms")


def trickles_and_silence(port):
    print("\n## Trickled bodies and silent sockets\n")
    trickling = []
    for _ in range(50):
        s = socket.create_connection(("127.0.0.1", port))
        s.sendall(b"POST /slope/spencer HTTP/1.1\r\nHost: x\r\ncontent-type: application/json\r\ncontent-length: 100000\r\n\r\n")
        s.setblocking(False)
        trickling.append(s)
    silent = []
    for _ in range(1100):
        try:
            silent.append(socket.create_connection(("127.0.0.1", port), timeout=2))
        except OSError:
            break
    time.sleep(0.3)
    # As a liveness probe would: up to 5 tries, 0.5 s apart.
    health = None
    for attempt in range(1, 6):
        try:
            with urllib.request.urlopen(f"http://127.0.0.1:{port}/healthz", timeout=5) as r:
                health = f"{r.status} at try {attempt}"
                break
        except Exception as error:
            health = repr(error)
            time.sleep(0.5)
    start = time.perf_counter()
    cut = set()
    while time.perf_counter() - start < 40 and len(cut) < len(trickling):
        for i, s in enumerate(trickling):
            if i in cut:
                continue
            try:
                if s.recv(64):
                    cut.add(i)
                    continue
            except BlockingIOError:
                pass
            except OSError:
                cut.add(i)
                continue
            try:
                s.send(b" ")
            except OSError:
                cut.add(i)
        time.sleep(0.5)
    print(f"{len(silent)} silent sockets open: /healthz answered {health}; "
          f"50 bodies trickled a byte every 0.5 s: {len(cut)} cut off within {time.perf_counter() - start:.1f} s "
          f"(body deadline 30 s)")
    for s in silent + trickling:
        s.close()


def sigterm_under_load():
    print("\n## SIGTERM under load (drain 2 s)\n")
    proc, port = start_server({"THRUSTLINE_DRAIN_SECS": "2"})
    threads = [threading.Thread(target=send, args=(port, PROBE[3][1], PROBE[3][2]), daemon=True) for _ in range(6)]
    for t in threads:
        t.start()
    time.sleep(0.5)
    start = time.perf_counter()
    proc.send_signal(signal.SIGTERM)
    proc.wait(timeout=60)
    print(f"six searches to the time limit running: the process exited {time.perf_counter() - start:.2f} s after SIGTERM, status {proc.returncode}")


proc, port = start_server()
try:
    if not only_mixed:
        probe(port, proc.pid)
    mixed_load(port, proc.pid, 150, seconds)
    if not only_mixed:
        disconnects(port)
        trickles_and_silence(port)
    print(f"\npeak RSS over the whole run: {peak_mib(proc.pid):.0f} MiB")
finally:
    proc.terminate()
    proc.wait()
if not only_mixed:
    sigterm_under_load()
