#!/usr/bin/env bash
# Runs every benchmark program in BUILD_DIR/bench. Google Benchmark programs report medians of repetitions;
# plain programs print their own tables. See docs/benchmarks.md for the figures and how to read them.
set -euo pipefail
build_dir=${1:?usage: run_benchmarks.sh BUILD_DIR}
for program in "$build_dir"/bench/*; do
  [ -x "$program" ] && [ -f "$program" ] || continue
  echo "== $(basename "$program")"
  "$program"
done
