#!/usr/bin/env bash
# every_asset.sh TOOL BIN LEVEL — runs one tool over every example animal on one level:
#   sim:    ossa-sim walks, runs, stops and turns round (a short script) and must exit 0
#           with no non-finite pose;
#   render: ossa-render draws the creature standing on the level's ground to a PNG.
# Registered with CTest (tools/CMakeLists.txt) once per tool and shipped level, and run under
# ASan+UBSan by tools/test: whatever the loaders accept must run without an error report.
# There (OSSA_SAMPLE=1) it visits the sample of tests/shared/sanitizer_sample.txt for its key
# (assets:LEVEL or render:LEVEL), which reaches every line and branch outcome the full sweep
# reaches (tools/sanitizer-sample); with OSSA_SWEEP_ONLY=NAME, that one animal alone.
set -u
tool="$1" bin="$2" level="$3"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
out="${OSSA_ASSET_OUT:-$(mktemp -d)}"
mkdir -p "$out"
failed=0 count=0
all_names() { grep -o '"name": "[^"]*"' "$root/assets/creatures/examples.json" | sed 's/"name": "\(.*\)"/\1/'; }
key="$([ "$tool" = sim ] && echo assets || echo "$tool"):$(basename "$level")"
sample_names() { sed -n "s/^$key animal //p" "$root/tests/shared/sanitizer_sample.txt"; }
if [ -n "${OSSA_SWEEP_ONLY:-}" ]; then
  names=$(all_names | grep -x -F -e "$OSSA_SWEEP_ONLY" || true)
elif [ "${OSSA_SAMPLE:-0}" = "1" ]; then
  names=$(all_names | grep -x -F -f <(sample_names) || true)
else
  names=$(all_names)
fi
expected=$(grep -c . <<<"$names")
while IFS= read -r name; do
  count=$((count + 1))
  case "$tool" in
    sim)
      if ! result=$("$bin" --example "$name" --level "$level" --script "walk:0.6:1.5,run:1:1,stop:0.5,walk:-0.6:1" --json 2>&1); then
        echo "FAIL ossa-sim $name on $level: $result"; failed=$((failed + 1))
      elif ! grep -q '"nan_count": 0' <<<"$result"; then
        echo "FAIL ossa-sim $name on $level: non-finite pose"; failed=$((failed + 1))
      fi ;;
    render)
      png="$out/$(basename "$level" .json)-${name// /_}.png"
      if ! result=$("$bin" --example "$name" --level "$level" --png "$png" 2>&1) || [ ! -s "$png" ]; then
        echo "FAIL ossa-render $name on $level: $result"; failed=$((failed + 1))
      fi ;;
    *) echo "unknown tool $tool"; exit 2 ;;
  esac
done <<<"$names"
echo "$tool: $count examples on $(basename "$level"), $failed failed"
[ "$count" -gt 0 ] && [ "$count" -eq "$expected" ] && { [ -n "${OSSA_SWEEP_ONLY:-}" ] || [ "${OSSA_SAMPLE:-0}" = "1" ] || [ "$count" -eq 44 ]; } && [ "$failed" -eq 0 ]
