#!/usr/bin/env bash
# Runs one fuzz target (or all of them, one after the other) for SECONDS each (docs/fuzzing.md):
#   fuzz/run.sh TARGET|all SECONDS [extra libFuzzer flags...]
# The fuzzers are built by:
#   CC=clang-14 CXX=clang++-14 cmake -S . -B build-fuzz-clang -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
#     -DCURVESCAN_BUILD_FUZZERS=ON -DCURVESCAN_BUILD_TESTS=OFF -DCURVESCAN_BUILD_BENCH=OFF -DCURVESCAN_BUILD_TOOLS=OFF
#   cmake --build build-fuzz-clang --target fuzz_<target>...
# FUZZ_BUILD_DIR picks another build directory. Each run starts from fuzz/corpus/<target>/ plus
# fuzz/regressions/<target>/, copied into a scratch directory, so the committed corpus never grows by
# accident; the inputs it found are dropped at the end unless FUZZ_KEEP_DIR=<dir> names a directory to
# copy them to. A crash, hang (> 10 s for one input) or OOM (> 2 GiB) is written to
# $FUZZ_BUILD_DIR/fuzz-artifacts/<target>/ and makes this script exit non-zero. Each run appends
# "target seconds executions exit-status" to $FUZZ_BUILD_DIR/fuzz-runs.tsv (the figures of docs/fuzzing.md).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
build_dir=${FUZZ_BUILD_DIR:-$root/build-fuzz-clang}
# The target names, as fuzz/CMakeLists.txt lists them (it writes them into the build directory).
targets=()
if [ -f "$build_dir/fuzz/fuzz-targets.txt" ]; then mapfile -t targets <"$build_dir/fuzz/fuzz-targets.txt"; fi

if [ $# -lt 2 ]; then
  echo "usage: fuzz/run.sh TARGET|all SECONDS [libFuzzer flags...]; targets: ${targets[*]:-(configure $build_dir first)}" >&2
  exit 64
fi
which=$1 seconds=$2
shift 2

dictionary_for() {
  case "$1" in
    svg_path_data | svg_document) echo "$here/dict/svg.dict" ;;
    curve_spec) echo "$here/dict/json.dict" ;;
    png_read | image_diff) echo "$here/dict/png.dict" ;;
    css) echo "$here/dict/css.dict" ;;
    expression) echo "$here/dict/expression.dict" ;;
    *) echo "" ;;
  esac
}

run_one() {  # target
  local target=$1
  shift
  local binary=$build_dir/fuzz/fuzz_$target
  if [ ! -x "$binary" ]; then
    echo "fuzz/run.sh: $binary is missing; build it first (see the top of this script)" >&2
    return 1
  fi
  local scratch artifacts log dictionary status=0
  scratch=$(mktemp -d "${TMPDIR:-/tmp}/curvescan-fuzz-$target.XXXXXX")
  artifacts=$build_dir/fuzz-artifacts/$target
  mkdir -p "$scratch/corpus" "$artifacts"
  cp -r "$here/corpus/$target/." "$scratch/corpus/"
  if [ -d "$here/regressions/$target" ]; then cp -r "$here/regressions/$target/." "$scratch/corpus/"; fi
  rm -f "$scratch/corpus/README.md"
  log=$scratch/log
  # -print_funcs=0: libFuzzer otherwise starts llvm-symbolizer to name each newly covered function in a
  # NEW_FUNC line, which this script never shows; early in a run that was half of text_layout's CPU time.
  local flags=(-max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -print_funcs=0
               -artifact_prefix="$artifacts/")
  dictionary=$(dictionary_for "$target")
  if [ -n "$dictionary" ]; then flags+=(-dict="$dictionary"); fi
  echo "== fuzz_$target for $seconds s (corpus: $(ls "$scratch/corpus" | wc -l) files) =="
  ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1} \
    UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1} \
    "$binary" "${flags[@]}" "$@" "$scratch/corpus" >"$log" 2>&1 || status=$?
  grep -E "^stat::|^(==[0-9]+==)?ERROR|^SUMMARY|Test unit written|^artifact_prefix" "$log" || true
  local executions
  executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  # -fork=N runs (e.g. with -ignore_timeouts=1 to get past a known slow input) print no final stats; their
  # progress lines start with "#<executions>:".
  if [ -z "$executions" ]; then executions=$(sed -n 's/^#\([0-9]*\): .*/\1/p' "$log" | tail -1); fi
  printf '%s\t%s\t%s\t%s\n' "$target" "$seconds" "${executions:-0}" "$status" >>"$build_dir/fuzz-runs.tsv"
  if [ -n "${FUZZ_KEEP_DIR:-}" ]; then mkdir -p "$FUZZ_KEEP_DIR/$target" && cp -r "$scratch/corpus/." "$FUZZ_KEEP_DIR/$target/"; fi
  if [ "$status" -ne 0 ]; then
    echo "fuzz_$target FAILED (exit $status); the last lines of its log:" >&2
    tail -60 "$log" >&2
    echo "reproduce: $binary <input from $artifacts/>" >&2
  fi
  rm -rf "$scratch"
  return "$status"
}

if [ "$which" = all ]; then
  if [ ${#targets[@]} -eq 0 ]; then
    echo "fuzz/run.sh: $build_dir/fuzz/fuzz-targets.txt is missing; configure and build the fuzzers first" >&2
    exit 1
  fi
  failed=()
  for target in "${targets[@]}"; do run_one "$target" "$@" || failed+=("$target"); done
  if [ ${#failed[@]} -ne 0 ]; then
    echo "fuzz/run.sh: failed: ${failed[*]}" >&2
    exit 1
  fi
else
  run_one "$which" "$@"
fi
