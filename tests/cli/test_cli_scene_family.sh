#!/usr/bin/env bash
# The procedural family (scene/builtin_scene_family.h, issue 46) as a user
# meets it: every kind, at two seeds, written twice gives the same .glb
# bytes and another seed other bytes; each written file loads again as a
# glTF with its camera and renders an AO whose mean is well above 0 (a
# camera inside geometry would see AO near 0) and below 1 (the clutter
# occludes); names that are not members are refused in one line.
gtlab=$1
work=$2
rm -rf "$work" && mkdir -p "$work"
source "$(dirname "$0")/cli_test_lib.sh"

for kind in room railing street props foliage edges terrain; do
  for seed in 0 7; do
    name=$kind-$seed
    "$gtlab" scene write "$name" -o "$work/$name.glb" >/dev/null &&
      "$gtlab" scene write "$name" -o "$work/$name.again.glb" >/dev/null || { fail "$name: not written"; continue; }
    cmp -s "$work/$name.glb" "$work/$name.again.glb" && pass || fail "$name: two writes differ"
  done
  cmp -s "$work/$kind-0.glb" "$work/$kind-7.glb" && fail "$kind: seeds 0 and 7 give the same scene" || pass
  run render ao --scene "$work/$kind-0.glb" --width 48 --height 48 --spp 8 -o "$work/$kind.exr"
  [ "$status" -eq 0 ] || { fail "$kind: render: $(cat "$work/stderr")"; continue; }
  mean=$("$gtlab" compare "$work/$kind.exr" "$work/$kind.exr" --channel ao.V | awk '/mean A/ {print $3}')
  covered=$("$gtlab" compare "$work/$kind.exr" "$work/$kind.exr" --channel ao.V | awk '/pixels inside/ {print $4}')
  awk -v m="$mean" -v c="$covered" 'BEGIN { exit !(m > 0.4 && m < 0.99 && c > 0.3 * 48 * 48) }' && pass ||
    fail "$kind: mean AO $mean over $covered pixels (want 0.4 < mean < 0.99 over a third of the image)"
done

expect_error leading-zero "builtin:room-07: unknown built-in scene" "" -- scene write room-07 -o "$work/x.glb"
expect_error no-seed "builtin:room-: unknown built-in scene" "" -- scene write room- -o "$work/x.glb"
expect_error too-large "builtin:street-10000: unknown built-in scene" "" -- scene write street-10000 -o "$work/x.glb"
finish
