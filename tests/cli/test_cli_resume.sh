#!/usr/bin/env bash
# Resume (issue 20, raytracer/render_checkpoint.h): a render stopped after
# some blocks (the test hook GTLAB_STOP_AFTER_BLOCKS, as SIGTERM would),
# by a real SIGTERM, or killed (SIGKILL, with a checkpoint after every
# block) leaves F.checkpoint.exr and no F.exr; `--resume` finishes it into
# the same file, byte for byte, as the uninterrupted render, and removes the
# checkpoint. A checkpoint of another render is refused. Renders with a
# stopping target checkpoint by rows, with the same guarantee; so do the
# other reference types (multibounce, specular-occlusion, sphere-light, fog).
gtlab=$1
work=$2
rm -rf "$work" && mkdir -p "$work"
source "$(dirname "$0")/cli_test_lib.sh"
cd "$work" || exit 1

small=(ao --scene builtin:cornell --width 24 --height 16 --spp 320 --seed 9 --threads 1)
expect_ok whole render "${small[@]}" -o whole.exr

# stopped_render NAME STATUS ARGS...: gtlab must exit with STATUS, leave a
# checkpoint and no output.
stopped_render() {
  local name=$1 expected=$2
  shift 2
  "$gtlab" render "$@" -o r.exr >/dev/null 2>stderr.txt
  local status=$?
  [ "$status" -eq "$expected" ] && pass || fail "$name: exit status $status, expected $expected: $(cat stderr.txt)"
  [ ! -e r.exr ] && [ -s r.checkpoint.exr ] && pass || fail "$name: r.exr written or no r.checkpoint.exr"
}
# Stopped after 2 blocks, resumed and stopped after 1 more, resumed to the end.
GTLAB_STOP_AFTER_BLOCKS=2 stopped_render hook-1 143 "${small[@]}"
GTLAB_STOP_AFTER_BLOCKS=1 stopped_render hook-2 143 "${small[@]}" --resume
# A checkpoint is not a part to merge: said so (issue 41: it was called a gtlab.quantity mismatch).
expect_error merge-checkpoint "r.checkpoint.exr: is the checkpoint of an unfinished render, not a part to merge" merged.exr -- merge whole.exr r.checkpoint.exr -o merged.exr
expect_ok resume render "${small[@]}" --resume -o r.exr
cmp -s whole.exr r.exr && pass || fail "stopped twice and resumed: not the uninterrupted file"
[ ! -e r.checkpoint.exr ] && pass || fail "the checkpoint stayed after the render finished"

# Another render's checkpoint (seed 10) is refused by --resume.
other=(ao --scene builtin:cornell --width 24 --height 16 --spp 320 --seed 10 --threads 1)
rm -f r.exr
GTLAB_STOP_AFTER_BLOCKS=1 stopped_render other 143 "${other[@]}"
# It says what differs (issue 41): the seed, as gtlab.seed.
expect_error other-checkpoint "r.checkpoint.exr: a checkpoint of another render (its gtlab.seed is 10 there, 9 here)" r.exr -- render "${small[@]}" --resume -o r.exr
rm -f r.checkpoint.exr

# Checkpoints of the output from a run on another number of processes
# (mpirun -n N leaves F.checkpoint.rank<r>-of-<N>.exr) are refused by
# --resume, naming the file; a temporary, or another output's, is not one.
mkdir -p sub && touch sub/r.checkpoint.rank1-of-4.exr.writing-7 sub/r2.checkpoint.rank0-of-2.exr
expect_ok not-ours render "${small[@]}" --resume -o sub/r.exr
touch sub/r.checkpoint.rank1-of-4.exr
expect_error other-count "sub/r.checkpoint.rank1-of-4.exr: a checkpoint of this output from a run on 4 process(es), this one has 1: resume it with mpirun -n 4, or remove it" \
  sub/r.exr -- render "${small[@]}" --resume -o sub/r.exr
rm -rf sub

# A render with a stopping target checkpoints by rows (8 at a time here):
# stopped after 1 block of rows, resumed, the bits of the whole render.
adaptive=(ao --scene builtin:cornell --width 24 --height 20 --spp 4096 --target-stderr 0.02 --seed 9 --threads 1)
expect_ok adaptive-whole render "${adaptive[@]}" -o adaptive.exr
GTLAB_STOP_AFTER_BLOCKS=1 stopped_render adaptive-stop 143 "${adaptive[@]}"
GTLAB_STOP_AFTER_BLOCKS=1 stopped_render adaptive-stop-2 143 "${adaptive[@]}" --resume
expect_ok adaptive-resume render "${adaptive[@]}" --resume -o r.exr
cmp -s adaptive.exr r.exr && pass || fail "adaptive, stopped twice and resumed: not the uninterrupted file"
rm -f r.exr r.checkpoint.exr

# The other reference types (several quantities each, which the checkpoint
# lists in its channels' order, not the integrator's): stopped after one
# block, resumed, the bits of the whole render.
size=(--width 12 --height 8 --seed 3 --threads 1 --spp 130)
for name in "${!other_references[@]}"; do
  read -r -a args <<<"${other_references[$name]}"
  expect_ok "$name-whole" render "${args[@]}" "${size[@]}" -o "$name.exr"
  GTLAB_STOP_AFTER_BLOCKS=1 stopped_render "$name-stop" 143 "${args[@]}" "${size[@]}"
  expect_ok "$name-resume" render "${args[@]}" "${size[@]}" --resume -o r.exr
  cmp -s "$name.exr" r.exr && pass || fail "$name, stopped and resumed: not the uninterrupted file"
  rm -f r.exr r.checkpoint.exr
done

# Real signals: SIGTERM, then SIGKILL (a killed job), once a checkpoint
# exists (written after every block here); each resumed to the same file.
big=(ao --scene builtin:cornell --width 48 --height 32 --spp 1600 --seed 4 --threads 1)
expect_ok big-whole render "${big[@]}" -o big.exr
for signal in TERM KILL; do
  rm -f r.exr r.checkpoint.exr
  GTLAB_CHECKPOINT_SECONDS=0 "$gtlab" render "${big[@]}" -o r.exr >/dev/null 2>&1 &
  pid=$!
  for _ in $(seq 600); do [ -e r.checkpoint.exr ] && break; sleep 0.05; done
  kill -s "$signal" "$pid"
  wait "$pid"
  status=$?
  expected=$((128 + $(kill -l "$signal")))
  [ "$status" -eq "$expected" ] && pass || fail "SIG$signal: exit status $status, expected $expected (finished first?)"
  [ ! -e r.exr ] && [ -s r.checkpoint.exr ] && pass || fail "SIG$signal: r.exr written or no checkpoint"
  expect_ok "resume-$signal" render "${big[@]}" --resume -o r.exr
  cmp -s big.exr r.exr && pass || fail "SIG$signal and resumed: not the uninterrupted file"
done

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
