#!/usr/bin/env bash
# The sphere-light verbs as a user runs them: bad input gives one error line
# and no output; small runs write every promised file, with sane contents.
gtlab=$1
work=$2
rm -rf "$work" && mkdir -p "$work"
source "$(dirname "$0")/../../../tests/cli/cli_test_lib.sh"
fit=$work/fit.json

expect_error check-unknown "nope: unknown check" "" -- check nope
expect_error check-steps "--steps: 1 is out of range" "" -- check sphere-noh --steps 1 -o "$work/noh"
expect_error fit-unknown "nope: unknown fit problem" "" -- fit nope
expect_error fit-no-output "fit sphere-light: no output given" "" -- fit sphere-light --train 100
expect_error fit-train "--train: 'many' is not a whole number" "$fit" -- fit sphere-light --train many -o "$fit"
expect_error fit-unwritable "nowhere/fit.json: cannot write" "" -- fit sphere-light --train 100 -o "$work/nowhere/fit.json"
expect_error bench-count "--count: 5 is out of range" "" -- bench sphere-light --count 5

exr=$work/sphere.exr
expect_error render-no-radius "sphere-light needs --light-position and --light-radius" "$exr" -- render sphere-light --scene builtin:plane --light-position 0,2,0 -o "$exr"
expect_error render-bad-position "--light-position: '0,2' is not three numbers" "$exr" -- render sphere-light --scene builtin:plane --light-position 0,2 --light-radius 1 -o "$exr"
expect_error render-radius-ao "--light-radius: applies to sphere-light only" "$exr" -- render ao --scene builtin:plane --light-radius 1 -o "$exr"
expect_ok render-small render sphere-light --scene builtin:plane --light-position 0,2,-3 --light-radius 0.5 --width 16 --height 16 --spp 16 -o "$exr"
[ -s "$exr" ] && pass || fail "render sphere-light wrote nothing"
expect_error render-shadows-ao "--shadows: applies to sphere-light only" "$exr.ao" -- render ao --scene builtin:plane --shadows -o "$exr.ao"
expect_ok render-shadows render sphere-light --scene builtin:sphere-on-plane --light-position 0,6,0 --light-radius 0.3 --shadows --width 16 --height 16 --spp 16 -o "$work/shadowed.exr"

for verb in "check sphere-noh" "fit sphere-light"; do
  expect_ok "help-$verb" $verb --help
done

expect_ok check-small check sphere-noh --steps 4 --rim-steps 64 -o "$work/noh"
for f in sphere_noh.csv sphere_noh_map.csv sphere_noh_by_nv.csv sphere_noh_map.png sphere_noh_error.png; do
  [ -s "$work/noh/$f" ] && pass || fail "check sphere-noh did not write $f"
done
lines=$(wc -l <"$work/noh/sphere_noh.csv")
[ "$lines" -eq 257 ] && pass || fail "sphere_noh.csv has $lines lines, expected 1 + 4^4"
no_leftovers "$work/noh"

expect_ok fit-small fit sphere-light --train 300 --test 200 --samples 128 --threads 2 -o "$fit"
for f in fit.json fit.h fit.hlsl fit.glsl; do
  [ -s "$work/$f" ] && pass || fail "fit sphere-light did not write $f"
done
# Fitted values with positive standard errors; the refit beats the published
# constants on the held-out configurations.
python3 - "$fit" <<'PY' && pass || fail "fit.json contents"
import json, math, sys
j = json.load(open(sys.argv[1]))
for k in ("radius_reduction", "norm_scale", "norm_alpha"):
    v, s = j["values"][k], j["standard_errors"][k]
    assert math.isfinite(v) and s > 0, (k, v, s)
h = j["held_out_errors"]
assert h["decima_refit"]["rms_log_error"] < h["decima_published"]["rms_log_error"], h
PY
expect_shader_compiles sl-hlsl "$work/fit.hlsl" hlsl \
  "float4(EvaluateSphericalAreaGGX(v.x, v.y, v.z, v.w, 0.1, 0.3, float3(0.04, 0.04, 0.04)), GetNoHSquared(0.1, v.x, v.y, v.z))"
expect_shader_compiles sl-glsl "$work/fit.glsl" glsl \
  "vec4(EvaluateSphericalAreaGGX(v.x, v.y, v.z, v.w, 0.1, 0.3, vec3(0.04)), GetNoHSquared(0.1, v.x, v.y, v.z))"
no_leftovers "$work"

# gtlab lut ltc: the GGX LTC table, its four files, the same bits for 1 and 2 threads.
expect_error lut-ltc-size "--size: 2 is out of range" "$work/ltc/ltc_ggx.exr" -- lut ltc --size 2 -o "$work/ltc"
expect_ok lut-ltc lut ltc --size 8 --threads 2 -o "$work/ltc"
for f in ltc_ggx.exr ltc_ggx.h ltc_ggx.hlsl ltc_ggx.glsl; do
  [ -s "$work/ltc/$f" ] && pass || fail "lut ltc did not write $f"
done
expect_ok lut-ltc-one-thread lut ltc --size 8 --threads 1 -o "$work/ltc1"
cmp -s "$work/ltc/ltc_ggx.h" "$work/ltc1/ltc_ggx.h" && pass || fail "lut ltc differs between 1 and 2 threads"
no_leftovers "$work/ltc"

# Same seed, same bits, whatever the thread count.
expect_ok fit-one-thread fit sphere-light --train 300 --test 200 --samples 128 --threads 1 -o "$work/fit1.json"
cmp -s "$work/fit.h" "$work/fit1.h" && pass || fail "fit differs between 1 and 2 threads"
finish
