#!/usr/bin/env bash
# Environment-lit references as a user runs them (issue 28): env-diffuse
# and env-specular under a Blender HDR (DWAB EXR), the sky and the sun,
# blocks merging into the whole render (the white dome against multibounce:
# techniques/environment/tests/test_environment_render.c), `bench env-diffuse`'s verdict on
# its ratio, and
# bad input (one error line naming the file or option, exit 1, no output).
gtlab=$1
work=$2
rm -rf "$work" && mkdir -p "$work"
source "$(dirname "$0")/cli_test_lib.sh"

sunset=/usr/share/blender/datafiles/studiolights/world/sunset.exr
common=(--scene builtin:corner --width 24 --height 20)
expect_ok render-hdr render env-diffuse "${common[@]}" --spp 16 --environment "$sunset" --env-rotate 90 --env-intensity 2 --albedo 0.5 --bounces 2 -o "$work/hdr.exr"
expect_ok render-sun render env-specular "${common[@]}" --spp 16 --environment sun --roughness 0.3 --f0 0.04 -o "$work/sun.exr"
# two blocks merge into the whole render
expect_ok render-whole render env-diffuse "${common[@]}" --spp 16 --environment sky -o "$work/sky.exr" --albedo scene
expect_ok render-b1 render env-diffuse "${common[@]}" --spp 8 --environment sky -o "$work/b1.exr" --albedo scene
expect_ok render-b2 render env-diffuse "${common[@]}" --spp 8 --sample-offset 8 --environment sky -o "$work/b2.exr" --albedo scene
expect_ok merge merge "$work/b1.exr" "$work/b2.exr" -o "$work/merged.exr"
for channel in env_diffuse.R env_diffuse_direct.B.stderr env_diffuse_unoccluded.G; do
  run compare "$work/sky.exr" "$work/merged.exr" --channel "$channel" --json
  cp "$work/stdout" "$work/merged.json"
  json_is max_abs == 0 "$work/merged.json" && pass || fail "merged $channel differs: $(cat "$work/merged.json")"
done
# the throughput bench prints its ratio and whether issue 28's goal (>= 0.7) is met, agreeing with that ratio
expect_ok bench bench env-diffuse --scene builtin:corner --width 16 --height 16 --spp 2 --repeats 1 --threads 1
line=$(grep '^ratio env-diffuse / multibounce samples/s: ' "$work/stdout")
python3 - "$line" <<'PY' && pass || fail "bench: no ratio line agreeing with its verdict: '$line'"
import re, sys
m = re.fullmatch(r"ratio [^:]*: ([0-9.]+) \(goal >= 0\.7: (met|not met)\)", sys.argv[1])
ratio = float(m.group(1)) if m else None
sys.exit(0 if m and (abs(ratio - 0.7) <= 5e-4 or (ratio >= 0.7) == (m.group(2) == "met")) else 1)
PY
expect_error other-light "gtlab.settings" "$work/x.exr" -- merge "$work/b1.exr" "$work/hdr.exr" -o "$work/x.exr"
expect_error missing-file "$work/none.exr: cannot open: no such file (an environment is white, sky, sun or an HDR image)" "$work/x.exr" -- render env-diffuse "${common[@]}" --environment "$work/none.exr" --albedo 0.5 -o "$work/x.exr"
expect_error not-an-hdr "$work/sky.exr" "$work/x.exr" -- render env-diffuse "${common[@]}" --environment "$work/sky.exr" --albedo 0.5 -o "$work/x.exr"
expect_error rotate-ao "--env-rotate: applies to env-diffuse and env-specular only" "$work/x.exr" -- render ao --scene builtin:corner --env-rotate 10 -o "$work/x.exr"
expect_error f0-diffuse "--f0: applies to env-specular only" "$work/x.exr" -- render env-diffuse --scene builtin:corner --f0 0.5 --albedo 0.5 -o "$work/x.exr"
expect_error two-albedos "takes one grey albedo or 'scene'" "$work/x.exr" -- render env-diffuse "${common[@]}" --albedo 0.2,0.4 -o "$work/x.exr"
expect_error so-file "--environment: '$sunset' is neither white nor sky" "$work/x.exr" -- render specular-occlusion --scene builtin:corner --environment "$sunset" -o "$work/x.exr"
expect_error bad-intensity "--env-intensity" "$work/x.exr" -- render env-specular --scene builtin:corner --env-intensity -1 -o "$work/x.exr"
finish
