#!/usr/bin/env bash
# Regenerates docs/evidence-screenshot.png: a certify run of the example candidate with its
# planted bug (so the page shows a divergence, its minimized input and the plot's red move),
# rendered by headless Chromium. Run from the repository root; needs python3 and chromium
# (Debian: apt-get install -y chromium).
set -euo pipefail
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
cargo build --release --quiet --bin cyclecheck
target/release/cyclecheck certify --cycles g92 --cases 200 --out "$out/evidence" \
    --candidate 'python3 examples/g92_candidate.py --plant-bug' >/dev/null || true
browser=$(command -v chromium || command -v chromium-browser || command -v google-chrome)
"$browser" --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size=1400,1800 \
    --screenshot="$out/shot.png" "file://$out/evidence/index.html" 2>/dev/null
cp "$out/shot.png" docs/evidence-screenshot.png
echo "wrote docs/evidence-screenshot.png"
