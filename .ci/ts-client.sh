#!/usr/bin/env bash
# A TypeScript client generated from the committed openapi/openapi.json (openapi-typescript types,
# openapi-fetch calls; versions pinned in .ci/ts-client/package.json), with every documented
# request body typed against its route (.ci/ts_examples.py), compiled with `tsc --strict` and run
# against a running server: fails when a documented body or a call does not type-check, or when
# an answer is not what the docs say.
# Usage: .ci/ts-client.sh BASE_URL
set -euo pipefail
cd "$(dirname "$0")/.."
base_url=$1
if ! command -v npm >/dev/null 2>&1; then
    echo "installing Node.js and npm from Debian's packages"
    apt-get update -qq && apt-get install -y -qq nodejs npm >/dev/null
fi
# The packages are kept between runs; what a run writes lives in a folder of its own.
modules="${TMPDIR:-/tmp}/thrustline-ts-client"
mkdir -p "$modules"
cp .ci/ts-client/package.json "$modules/"
(cd "$modules" && npm install --silent --no-audit --no-fund)
work="$(mktemp -d "${TMPDIR:-/tmp}/thrustline-ts.XXXXXX")"
trap 'rm -rf "$work"' EXIT
cp .ci/ts-client/check.ts .ci/ts-client/tsconfig.json .ci/ts-client/package.json "$work/"
ln -s "$modules/node_modules" "$work/node_modules"
"$modules/node_modules/.bin/openapi-typescript" openapi/openapi.json -o "$work/schema.ts"
python3 .ci/ts_examples.py . "$work/examples.ts"
(cd "$work" && ./node_modules/.bin/tsc -p tsconfig.json)
node "$work/out/check.js" "$base_url"
