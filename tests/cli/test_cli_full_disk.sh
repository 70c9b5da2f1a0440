#!/usr/bin/env bash
# A full disk (issue 41, defect 3): every image and figure writer fails with
# one line naming the file, a non-zero exit, nothing under the final name
# and no temporaries — `gtlab compare --heatmap` (OpenImageIO), a report
# stage's gnuplot figure and plot data (`gtlab all --stages hdr-precision`),
# a LUT's files (`gtlab lut blue-noise`: EXR, then PNG). Two ways:
#  - always, without privilege: gtlab under `ulimit -f` with SIGXFSZ ignored,
#    so that a write past the limit fails with EFBIG (the limit is per file:
#    the largest file fails; a LUT's EXR is larger than its PNG);
#  - where the test may mount one (root), a small tmpfs filled up to the
#    point where the file under test no longer fits (ENOSPC): the LUT's EXR
#    fits and its PNG does not.
# Before issue 41 these runs exited 0 with truncated PNGs.
gtlab=$1
work=$2
awk -v w="$work/" 'index($2, w) == 1 {print $2}' /proc/mounts | xargs -r umount 2>/dev/null # an earlier run's, if killed
rm -rf "$work" && mkdir -p "$work/full"
source "$(dirname "$0")/cli_test_lib.sh"
"$gtlab" render ao --scene builtin:boxes --width 64 --height 64 --spp 4 -o "$work/a.exr" >/dev/null 2>&1 || fail "render a"
"$gtlab" render ao --scene builtin:boxes --width 64 --height 64 --spp 4 --seed 2 -o "$work/b.exr" >/dev/null 2>&1 ||
  fail "render b"

# limited KIB ARGS...: gtlab with a file size limit of KIB KiB, writes past it failing with EFBIG.
limited() {
  local kib=$1
  shift
  (trap '' XFSZ; ulimit -f "$kib"; exec "$gtlab" "$@") >"$work/stdout" 2>"$work/stderr"
  status=$?
}

# expect_write_failure NAME PATTERN DIR FILE...: the last run failed (status
# 1 or 2) with exactly one error line (progress lines "gtlab all: ..." and
# warnings aside) matching "gtlab: ...PATTERN", and left none of the FILEs
# (relative to DIR) and no temporary anywhere under DIR.
expect_write_failure() {
  local name=$1 pattern=$2 dir=$3 lines left
  shift 3
  lines=$(grep -v -e '^gtlab all: ' -e '^gtlab: warning: ' "$work/stderr" | wc -l)
  left=$(cd "$dir" && ls -d "$@" 2>/dev/null; find "$dir" -name '.*.tmp-*' -o -name '.*.bak-*')
  if [ "$status" -ne 1 ] && [ "$status" -ne 2 ]; then
    fail "$name: exit status $status, expected 1 or 2 (stderr: $(head -c 300 "$work/stderr"))"
  elif [ "$lines" -ne 1 ]; then
    fail "$name: $lines error lines on stderr, expected 1: $(head -c 500 "$work/stderr")"
  elif ! grep -q "^gtlab: .*$pattern" "$work/stderr"; then
    fail "$name: stderr does not match 'gtlab: ...$pattern': $(cat "$work/stderr")"
  elif [ -n "$left" ]; then
    fail "$name: left behind: $left"
  else
    pass
  fi
}

# The runs as they succeed, for the sizes of what they write.
expect_ok "compare" compare "$work/a.exr" "$work/b.exr" --heatmap "$work/full/h.png"
expect_ok "stage" all --quality preview --stages hdr-precision --threads 2 -o "$work/full/stage"
expect_ok "lut" lut blue-noise --size 64 --channels 1 -o "$work/full/lut"
size() { stat -c %s "$work/full/$1"; }
kib() { echo $((($1 + 1023) / 1024)); }
[ "$(size h.png)" -gt 1024 ] && [ "$(size stage/hdr_precision/code_steps.dat)" -lt "$(size stage/figures/hdr_code_steps.png)" ] &&
  [ "$(size stage/figures/hdr_code_steps.svg)" -lt "$(size stage/figures/hdr_code_steps.png)" ] && pass ||
  fail "the sizes this test relies on changed: $(ls -lR "$work/full")"

# ulimit: the heatmap; the stage's plot data, then its gnuplot PNG (the
# data fits, the figure does not); the LUT (its EXR, the larger file).
mkdir -p "$work/u"
limited 1 compare "$work/a.exr" "$work/b.exr" --heatmap "$work/u/h.png"
expect_write_failure "ulimit: compare --heatmap" "u/h.png: write failed: File too large" "$work/u" h.png
cp "$work/full/h.png" "$work/u/kept.png"
limited 1 compare "$work/a.exr" "$work/b.exr" --heatmap "$work/u/kept.png"
cmp -s "$work/full/h.png" "$work/u/kept.png" && pass || fail "ulimit: a heatmap that failed changed the file it replaces"
rm -f "$work/u/kept.png"
limited "$(($(size stage/hdr_precision/code_steps.dat) / 1024 - 1))" all --quality preview --stages hdr-precision --threads 2 \
  -o "$work/u/stage"
expect_write_failure "ulimit: stage plot data" "hdr_precision/code_steps.dat: write failed: File too large" "$work/u" \
  stage/hdr_precision/code_steps.dat stage/report.md stage/summary.json
limited "$(kib "$(size stage/hdr_precision/code_steps.dat)")" all --quality preview --stages hdr-precision --threads 2 \
  -o "$work/u/stage"
expect_write_failure "ulimit: stage gnuplot figure" "figures/hdr_code_steps.png: gnuplot could not write the whole PNG" \
  "$work/u" stage/figures/hdr_code_steps.png stage/figures/hdr_code_steps.svg stage/figures/hdr_code_steps.gp \
  stage/hdr_precision/code_steps.dat stage/report.md stage/summary.json
limited 2 lut blue-noise --size 64 --channels 1 -o "$work/u/lut"
expect_write_failure "ulimit: lut" "blue_noise_64.exr: " "$work/u" lut/blue_noise_64.exr lut/blue_noise_64.png

# tmpfs, where this test may mount one: filled so the named file does not fit.
mount_tmpfs() {  # DIR KIB
  mkdir -p "$1" && mount -t tmpfs -o "size=${2}k" tmpfs "$1" 2>/dev/null
}
pages_kib() { echo $(((($1 + 4095) / 4096) * 4)); }
mounted=()
trap 'for m in "${mounted[@]}"; do umount "$m"; done' EXIT
if [ "$(id -u)" -eq 0 ] && mount_tmpfs "$work/t_probe" 16; then
  umount "$work/t_probe"
  mount_tmpfs "$work/t_heatmap" 4 && mounted+=("$work/t_heatmap")
  head -c 4096 /dev/zero >"$work/t_heatmap/filler"
  run compare "$work/a.exr" "$work/b.exr" --heatmap "$work/t_heatmap/h.png"
  expect_write_failure "tmpfs: compare --heatmap" "h.png: write failed: No space left on device" "$work/t_heatmap" h.png
  # The stage: room for its plot data and kept script, not for the figure.
  room=$(($(pages_kib "$(size stage/hdr_precision/code_steps.dat)") + $(pages_kib "$(size stage/figures/hdr_code_steps.gp)")))
  mount_tmpfs "$work/t_stage" "$room" && mounted+=("$work/t_stage")
  run all --quality preview --stages hdr-precision --threads 2 -o "$work/t_stage/out"
  expect_write_failure "tmpfs: stage gnuplot figure" "figures/hdr_code_steps.png: gnuplot could not write the whole PNG" \
    "$work/t_stage" out/figures/hdr_code_steps.png out/figures/hdr_code_steps.gp out/hdr_precision/code_steps.dat out/report.md
  # The LUT: room for its EXR, not its PNG (OpenImageIO's writer).
  mount_tmpfs "$work/t_lut" "$(pages_kib "$(size lut/blue_noise_64.exr)")" && mounted+=("$work/t_lut")
  run lut blue-noise --size 64 --channels 1 -o "$work/t_lut/lut"
  expect_write_failure "tmpfs: lut PNG" "lut/blue_noise_64.png: write failed: No space left on device" "$work/t_lut" \
    lut/blue_noise_64.png lut/blue_noise_64.exr
else
  echo "no tmpfs (not root, or mount not permitted): the file size limit alone"
fi
finish
