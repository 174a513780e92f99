#!/usr/bin/env bash
# Browser test of the page at /: headless Chromium (Debian's package, installed here if missing)
# loads the page from a running release server; the page solves its seven examples on load
# (Milankovitch's dead load, a live load, the minimum thickness, a bridge with fill, passive
# restraint and rolling axles, Spencer's circle, the critical circle, a layered section). The
# test reads the rendered DOM for the numbers and the seven drawings, and keeps a screenshot in
# target/ci-artifacts/page.png.
# Usage: .ci/browser.sh   (builds the release binary if needed)
set -euo pipefail
cd "$(dirname "$0")/.."

if ! command -v chromium > /dev/null 2>&1; then
    echo "installing chromium from Debian's packages"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -q > /dev/null
    apt-get install -y -q chromium > /dev/null
fi
cargo build --release --locked --bin thrustline
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
./target/release/thrustline serve --addr "127.0.0.1:$port" > /dev/null 2>&1 &
server=$!
profile=$(mktemp -d)
trap 'kill "$server" 2>/dev/null || true; rm -rf "$profile"' EXIT
for _ in $(seq 50); do
    curl -fsS "http://127.0.0.1:$port/healthz" > /dev/null 2>&1 && break
    sleep 0.2
done
flags=(--headless --no-sandbox --disable-gpu --disable-quic --no-first-run
       --disable-background-networking --disable-component-update --disable-sync
       --user-data-dir="$profile" --virtual-time-budget=60000)
url="http://127.0.0.1:$port/"
dom=$(timeout 180 chromium "${flags[@]}" --dump-dom "$url" 2> /dev/null)
mkdir -p target/ci-artifacts
timeout 180 chromium "${flags[@]}" --window-size=1280,5200 --screenshot=target/ci-artifacts/page.png "$url" > /dev/null 2>&1 || true

failures=0
expect() {
    if grep -qF -- "$1" <<< "$dom"; then
        echo "ok: page shows $1"
    else
        echo "FAILED: page does not show $1" >&2
        failures=$((failures + 1))
    fi
}
# model §1.4: Milankovitch at D = 1.0747 collapses with hinges at 356 and 1446.
expect "dead_load_factor: 0   stable: false"
expect "356 (35.5°, intrados)"
expect "1446 (144.5°, intrados)"
expect "load_factor: 22.99688965"
# model §2.3 / thesis: F = 1.06958 at 100 slices.
expect "factor_of_safety: 1.06957"
expect "morgenstern_price: "
expect "solver: solved, assembly, 37 stops"
# Milankovitch's minimum D/R = 0.1075 (N = 200 voussoirs) and the critical circle of docs/slopes.md.
expect "thickness_to_radius: 0.1074"
expect "search: 1053 circles, 0 unsolved"
expect "factor_of_safety: 1.01457"
drawings=$( (grep -o '<img alt="drawing of the [a-z]* answer"[^>]*src="blob:' <<< "$dom" || true) | wc -l)
if [ "$drawings" -eq 7 ]; then echo "ok: seven drawings"; else echo "FAILED: $drawings drawings, expected 7" >&2; failures=$((failures + 1)); fi
# Each drawing decoded: its onload recorded a non-zero naturalWidth (a broken SVG stays at 0).
decoded=$( (grep -oE 'data-width="[1-9][0-9]*"' <<< "$dom" || true) | wc -l)
if [ "$decoded" -eq 7 ]; then echo "ok: seven drawings decoded (naturalWidth > 0)"; else echo "FAILED: $decoded drawings decoded, expected 7" >&2; failures=$((failures + 1)); fi
[ -s target/ci-artifacts/page.png ] && echo "screenshot: target/ci-artifacts/page.png"
passed=$((12 - failures))
echo "browser: $passed passed, $failures failed"
[ "$failures" -eq 0 ]
