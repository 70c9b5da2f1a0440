#!/usr/bin/env bash
# Runs the libFuzzer targets of a -DGTLAB_FUZZ=ON build (tests/fuzz/
# CMakeLists.txt), each for a bounded number of executions (RUNS; shader a
# tenth of it, see runs_of), two at a time, and prints how many executions
# each ran. A crash (or leak, sanitizer
# report, failed property, timeout, out-of-memory) fails the run and keeps
# the input that caused it in OUT/<target>/ (crash-*, leak-*, timeout-*,
# oom-*): copy it into tests/fuzz/regressions/<target>/ once fixed, so the
# normal suite replays it for ever.
#
#   tests/fuzz/run_fuzz.sh BUILD RUNS [TARGET...]
#     CI (.ci/run):  tests/fuzz/run_fuzz.sh build-fuzz 20000
#     by hand:       tests/fuzz/run_fuzz.sh build-fuzz 1000000
# FUZZ_OUT sets OUT (default BUILD/fuzz-out); FUZZ_JOBS the number of targets
# run at once (default 2); FUZZ_MAX_SECONDS caps each target's time (default
# none: RUNS executions, however long they take).
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$1
runs=$2
shift 2
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(json camera gltf exr merge fit_inputs shader)
out=${FUZZ_OUT:-$build/fuzz-out}
jobs=${FUZZ_JOBS:-2}

dictionary_of() {
  case $1 in
    json | camera) echo "$here/json.dict" ;;
    gltf) echo "$here/gltf.dict" ;;
    exr | fit_inputs) echo "$here/exr.dict" ;;
    merge) echo "$here/merge.dict" ;;
    shader) echo "$here/shader.dict" ;;
  esac
}

# The executions of a target: RUNS, but a tenth of it for shader, whose
# every input is a compilation with SPIRV-Tools' optimiser in a child
# process (about 50 ms of CPU, a thousand times a parser's input).
runs_of() {
  case $1 in
    shader) echo $((runs / 10 > 0 ? runs / 10 : 1)) ;;
    *) echo "$runs" ;;
  esac
}

# The memory limits of a target: 2560 MB of RSS, checked by libFuzzer's RSS
# thread. Not for shader: its every input forks a child (core/isolated_call.h),
# and the sanitizer runtimes of Debian 12 (clang 14, gcc 12) do not make
# their allocator safe across fork: a fork while the RSS thread, just
# started, is inside the allocator leaves the child waiting for ever on a
# lock no thread of it holds (measured: the first input, the empty one, hung
# in 5 runs of 5 with the thread, in none without). Its malloc limit, which
# libFuzzer checks in the calling thread, stays at 2560 MB; the child's memory is the
# child's own.
memory_limits_of() {
  case $1 in
    shader) echo "-rss_limit_mb=0 -malloc_limit_mb=2560" ;;
    *) echo "-rss_limit_mb=2560" ;;
  esac
}

# Runs one target; its log in OUT/<target>/log, its new inputs in
# OUT/<target>/corpus (the seeds in the source tree are only read).
run_target() {
  local target=$1 dir=$out/$1 start=$SECONDS
  rm -rf "$dir" && mkdir -p "$dir/corpus"
  local limits=(-runs="$(runs_of "$target")" -timeout=20 $(memory_limits_of "$target") -print_final_stats=1)
  [ -n "${FUZZ_MAX_SECONDS:-}" ] && limits+=(-max_total_time="$FUZZ_MAX_SECONDS")
  local corpora=("$dir/corpus" "$here/corpus/$target")
  [ -d "$here/regressions/$target" ] && corpora+=("$here/regressions/$target")
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "$build/tests/fuzz/fuzz_$target" "${limits[@]}" -dict="$(dictionary_of "$target")" \
    -artifact_prefix="$dir/" "${corpora[@]}" >"$dir/log" 2>&1
  local status=$? executions
  executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$dir/log" | tail -1)
  if [ $status -eq 0 ]; then
    echo "fuzz $target: ${executions:-?} executions in $((SECONDS - start)) s, no crash"
  else
    echo "fuzz $target: FAILED (status $status) after ${executions:-?} executions; input kept in $dir/:"
    grep -E "ERROR|SUMMARY|fuzz property|runtime error" "$dir/log" | head -5
    ls "$dir" | grep -E '^(crash|leak|timeout|oom|slow-unit)-' | head -3
  fi
  return $status
}

mkdir -p "$out"
failed=0
running=0
for target in "${targets[@]}"; do
  if [ ! -x "$build/tests/fuzz/fuzz_$target" ]; then
    echo "fuzz $target: $build/tests/fuzz/fuzz_$target is not built (cmake --build $build --target gtlab_fuzz_targets)"
    failed=1
    continue
  fi
  run_target "$target" &
  running=$((running + 1))
  if [ $running -ge "$jobs" ]; then
    wait -n || failed=1
    running=$((running - 1))
  fi
done
while [ $running -gt 0 ]; do
  wait -n || failed=1
  running=$((running - 1))
done
exit $failed
