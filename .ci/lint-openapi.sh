#!/usr/bin/env bash
# Lints the committed OpenAPI document as integrators' tools do: Redocly's `recommended` rules
# and Spectral's `spectral:oas`. Fails on any error (warnings are printed).
set -euo pipefail
cd "$(dirname "$0")/.."
dir="${TMPDIR:-/tmp}/thrustline-openapi-lint"
mkdir -p "$dir"
if ! command -v npm >/dev/null 2>&1; then
    echo "installing Node.js and npm from Debian's packages"
    apt-get update -qq && apt-get install -y -qq nodejs npm >/dev/null
fi
(cd "$dir" && npm install --silent --no-audit --no-fund \
    @redocly/cli@2.77.0 @stoplight/spectral-cli@6.16.3)
export REDOCLY_TELEMETRY=off REDOCLY_SUPPRESS_UPDATE_NOTICE=true
"$dir/node_modules/.bin/redocly" lint --extends=recommended openapi/openapi.json
printf 'extends: ["spectral:oas"]\n' > "$dir/.spectral.yaml"
"$dir/node_modules/.bin/spectral" lint --ruleset "$dir/.spectral.yaml" --fail-severity error \
    openapi/openapi.json
