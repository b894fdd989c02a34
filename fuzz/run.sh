#!/usr/bin/env bash
# Fuzzes one target of a MOLSURF_FUZZ=ON build for SECONDS, one job, from its seed corpus.
# New inputs go to OUT/corpus/NAME, crashes to OUT/artifacts/NAME-*; the seed corpus in
# the repository is only read. -max_len comes from the table in fuzz/CMakeLists.txt.
# Usage: fuzz/run.sh BUILD_DIR NAME SECONDS [OUT] [extra libFuzzer flags...]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="$1" name="$2" seconds="$3" out="${4:-$build/fuzz-runs}"
shift $(( $# < 4 ? $# : 4 ))
max_len=$(awk -v n="$name" '$1 == "\"" n { gsub(/"/, "", $3); print $3 }' "$here/CMakeLists.txt")
[[ -n "$max_len" ]] || { echo "run.sh: unknown target '$name'" >&2; exit 2; }
mkdir -p "$out/corpus/$name" "$out/artifacts"
exec "$build/fuzz/fuzz_$name" -max_total_time="$seconds" -max_len="$max_len" -rss_limit_mb=2048 \
  -timeout=10 -print_final_stats=1 -artifact_prefix="$out/artifacts/$name-" "$@" \
  "$out/corpus/$name" "$here/corpus/$name"
