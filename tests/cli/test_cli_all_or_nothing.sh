#!/usr/bin/env bash
# All or nothing (core/files/output_set.h), end to end: an output onto a device is
# refused and the device stays; an interrupted run exits 128 + signal, keeps
# the previous outputs as they were and leaves no temporary or backup. (The
# removal of temporaries and the roll-back themselves are proven in
# tests/core/test_output_set.c, where the signal arrives at a known point.)
gtlab=$1
work=$2
rm -rf "$work" && mkdir -p "$work"
source "$(dirname "$0")/cli_test_lib.sh"

# -o onto a character device.
expect_error device "/dev/null: .*not a regular file" "" -- render gbuffer --scene builtin:plane --width 16 --height 16 -o /dev/null
[ -c /dev/null ] && pass || fail "/dev/null is no longer a character device"

# A previous render, then the same command interrupted: SIGINT and SIGTERM.
out=$work/ao.exr
expect_ok first-render render ao --scene builtin:plane --width 16 --height 16 --spp 4 -o "$out"
before=$(md5sum "$out" "$work/ao.camera.json")
# SIGTERM and SIGHUP (a background job of a script ignores SIGINT, and so
# does gtlab then); the render must end within 30 s of the signal.
for signal in TERM HUP; do
  "$gtlab" render ao --scene builtin:menger --width 256 --height 256 --spp 1000000 -o "$out" >/dev/null 2>&1 &
  pid=$!
  sleep 1
  kill -s "$signal" "$pid"
  for _ in $(seq 300); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
  if kill -0 "$pid" 2>/dev/null; then
    kill -9 "$pid"
    fail "SIG$signal: gtlab still running 30 s after the signal"
  fi
  wait "$pid"
  status=$?
  expected=$((128 + $(kill -l "$signal")))
  [ "$status" -eq "$expected" ] && pass || fail "SIG$signal: exit status $status, expected $expected"
  [ "$(md5sum "$out" "$work/ao.camera.json")" = "$before" ] && pass || fail "SIG$signal: the previous outputs changed"
  hidden=$(ls -A "$work" | grep '^\.' || true)
  [ -z "$hidden" ] && pass || fail "SIG$signal: left $hidden"
done
# Scene identity is the content (gtlab.scene_hash): two different scenes
# written as s.glb in two folders and rendered from there do not merge; one
# scene reached by two paths does.
mkdir -p "$work/a" "$work/b"
printf '{"position":[3,4,5],"target":[0,0,0],"up":[0,1,0],"yfov_deg":45,"width":16,"height":16}' >"$work/cam.json"
"$gtlab" scene write plane -o "$work/a/s.glb" >/dev/null && "$gtlab" scene write corner -o "$work/b/s.glb" >/dev/null || fail "scene write"
(cd "$work/a" && "$gtlab" render ao --scene s.glb --camera ../cam.json --spp 4 -o ../p1.exr >/dev/null 2>&1) || fail "render a"
(cd "$work/b" && "$gtlab" render ao --scene s.glb --camera ../cam.json --spp 4 --sample-offset 4 -o ../p2.exr >/dev/null 2>&1) || fail "render b"
expect_error two-scenes-one-name "p2.exr: its gtlab.scene_hash differs" "$work/m.exr" -- merge "$work/p1.exr" "$work/p2.exr" -o "$work/m.exr"
expect_ok render-one-path render ao --scene "$work/a/s.glb" --camera "$work/cam.json" --spp 4 --sample-offset 4 -o "$work/p3.exr"
expect_ok one-scene-two-paths merge "$work/p1.exr" "$work/p3.exr" -o "$work/m.exr"
# Adaptive parts (--target-stderr) do not merge: their stop points differ
# from one adaptive render's.
expect_ok adaptive-1 render ao --scene builtin:plane --width 16 --height 16 --spp 128 --target-stderr 0.01 -o "$work/t1.exr"
expect_ok adaptive-2 render ao --scene builtin:plane --width 16 --height 16 --spp 128 --sample-offset 128 --target-stderr 0.01 -o "$work/t2.exr"
expect_error adaptive-merge "t1.exr: rendered with a stopping target" "$work/tm.exr" -- merge "$work/t1.exr" "$work/t2.exr" -o "$work/tm.exr"
finish
