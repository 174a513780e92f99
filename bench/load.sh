#!/usr/bin/env bash
# Load test of a running thrustline with wrk (Debian package `wrk`): throughput and latency
# percentiles for a small Spencer request and an N = 100 arch dead load at 1, 8 and 64
# concurrent connections, 5 s each, loopback only.
# Usage: bench/load.sh [BASE_URL]   (default http://127.0.0.1:8080; start the server first)
set -euo pipefail
base="${1:-http://127.0.0.1:8080}"
command -v wrk > /dev/null || { echo "wrk is not installed: apt-get install wrk" >&2; exit 1; }
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
cat > "$dir/spencer.lua" <<'LUA'
wrk.method = "POST"
wrk.headers["Content-Type"] = "application/json"
wrk.body = '{"slope":{"height":30.48,"length":60.96},"circle":{"x":9.63168,"y":63.76416},"slices":50,"soil":{"unit_weight":10,"cohesion":6.096,"friction_angle_deg":40,"pore_pressure_ratio":0.5}}'
LUA
cat > "$dir/arch.lua" <<'LUA'
wrk.method = "POST"
wrk.headers["Content-Type"] = "application/json"
wrk.body = '{"geometry":{"kind":"circular","radius":10,"thickness":1.0747,"voussoirs":100}}'
LUA
for script in spencer arch; do
    path=$([ "$script" = spencer ] && echo /slope/spencer || echo /arch/dead-load)
    for connections in 1 8 64; do
        threads=$(( connections < 2 ? 1 : 2 ))
        out=$(wrk -t "$threads" -c "$connections" -d 5s --latency -s "$dir/$script.lua" "$base$path")
        rps=$(echo "$out" | awk '/Requests\/sec/ {print $2}')
        p50=$(echo "$out" | awk '$1 == "50%" {print $2}')
        p99=$(echo "$out" | awk '$1 == "99%" {print $2}')
        errors=$(echo "$out" | awk '/Non-2xx|Socket errors/ {print}' | tr '\n' ' ')
        echo "| $path | $connections | $rps | $p50 | $p99 | ${errors:-none} |"
    done
done
