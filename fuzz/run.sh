#!/bin/sh
# run.sh TARGET SECONDS MAXLEN: one fuzzing session (one job, one worker) on the seeds and the
# corpus. FUZZ_SRC: a copy of the repository to build from (default: this one).
t=$1; secs=$2; maxlen=$3
here="$(cd "$(dirname "$0")" && pwd)"
src="${FUZZ_SRC:-$here/..}"
cd "$src/fuzz" || exit 1
export CARGO_TARGET_DIR="$here/target"
mkdir -p "$here/artifacts/$t"
cargo +nightly-2026-08-15 fuzz build "$t" || exit 1
cargo +nightly-2026-08-15 fuzz run "$t" "$here/corpus/$t" "$here/seeds/$t" -- \
  -artifact_prefix="$here/artifacts/$t/" \
  -max_total_time="$secs" -jobs=1 -workers=1 -timeout=10 -rss_limit_mb=2048 -max_len="$maxlen" -print_final_stats=1
