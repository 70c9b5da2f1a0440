#!/usr/bin/env bash
# gtlab fit multibounce as a user runs it: bad inputs give one line
# "gtlab: <file>: <problem>", exit 1 and no output; good references give the
# JSON, a C header that compiles and an HLSL file.
gtlab=$1
work=$2
rm -rf "$work" && mkdir -p "$work"
source "$(dirname "$0")/../../../tests/cli/cli_test_lib.sh"
out=$work/fit.json
small() { echo --width 24 --height 24 --spp 16; }

"$gtlab" render multibounce --scene builtin:corner --albedo 0.2,0.5,0.8 $(small) -o "$work/corner.exr" 2>/dev/null || fail "render corner"
"$gtlab" render multibounce --scene builtin:boxes --albedo 0.2,0.5,0.8 $(small) -o "$work/boxes.exr" 2>/dev/null || fail "render boxes"
"$gtlab" render multibounce --scene builtin:boxes --albedo 0.5 $(small) -o "$work/one.exr" 2>/dev/null || fail "render one albedo"
"$gtlab" render multibounce --scene builtin:boxes --albedo 0.2,0.5 --bounces inf $(small) -o "$work/inf.exr" 2>/dev/null || fail "render inf"
"$gtlab" render multibounce --scene builtin:boxes --albedo scene $(small) -o "$work/colour.exr" 2>/dev/null || fail "render colour"
"$gtlab" render ao --scene builtin:boxes $(small) -o "$work/ao.exr" 2>/dev/null || fail "render ao"
echo "not an image" >"$work/text.exr"

fit() { echo fit multibounce "$@" -o "$out"; }
expect_error missing-file "nowhere.exr: " "$out" -- $(fit --data "$work/nowhere.exr")
expect_error not-exr "text.exr: " "$out" -- $(fit --data "$work/text.exr")
expect_error ao-file "ao.exr: no multibounce channels" "$out" -- $(fit --data "$work/corner.exr" "$work/ao.exr")
expect_error coloured "colour.exr: coloured render" "$out" -- $(fit --data "$work/colour.exr")
expect_error one-albedo "--data: the joint model needs samples at 2 or more albedos" "$out" -- $(fit --data "$work/one.exr")
expect_error mixed-bounces "inf.exr: rendered with --bounces inf, but .*corner.exr with --bounces 4" "$out" -- $(fit --data "$work/corner.exr" "$work/inf.exr")
expect_error no-data "--data: no reference files" "$out" -- fit multibounce -o "$out"
expect_error no-output "-o: an output file is required" "" -- fit multibounce --data "$work/corner.exr"
expect_error unwritable "/nonexistent/fit.json: cannot write" "" -- fit multibounce --data "$work/corner.exr" -o /nonexistent/fit.json
expect_error stray-argument "unexpected argument 'extra.exr'" "$out" -- fit multibounce extra.exr -o "$out"
expect_error unknown-problem "fog: unknown fit problem" "" -- fit fog
expect_ok help fit multibounce --help
grep -q "^usage: gtlab fit multibounce" "$work/stdout" || fail "fit multibounce --help prints no usage"
expect_ok fit-help fit --help
grep -q "multibounce" "$work/stdout" || fail "fit --help does not list multibounce"

# Good data: two scenes, three albedos, data files after one --data.
expect_ok fit $(fit --data "$work/corner.exr" "$work/boxes.exr")
for f in "$work/fit.json" "$work/fit.h" "$work/fit.hlsl" "$work/fit.glsl"; do [ -s "$f" ] || fail "$f not written"; done
python3 - "$out" <<'PY' || fail "fit.json lacks what it promises"
import json, sys
j = json.load(open(sys.argv[1]))
assert j["data"]["files"][1].endswith("boxes.exr") and j["data"]["bounces"] == "4"
assert j["data"]["albedos"] == [0.2, 0.5, 0.8] and len(j["data"]["scenes"]) == 2
for key in ("a0", "a1", "b0", "b1", "c0", "c1"):
    assert key in j["joint_linear"]["coefficients"] and j["joint_linear"]["standard_errors"][key] > 0
assert len(j["joint_linear"]["covariance"]) == 6 and j["joint_linear"]["rmse"] > 0
assert j["talk_jimenez2016"]["coefficients"]["a1"] == 2.0404 and j["talk_jimenez2016"]["rmse"] > 0
assert len(j["per_albedo"]) == 3 and len(j["leave_one_scene_out"]["scenes"]) == 2
PY
# Same data, same bytes.
cp "$out" "$work/first.json"
expect_ok fit-again $(fit --data "$work/corner.exr" "$work/boxes.exr")
cmp -s "$out" "$work/first.json" || fail "a second fit of the same data wrote a different fit.json"
# The header is C an engine can compile, and its function is the fitted one.
cat >"$work/use_header.c" <<C
#include "fit.h"
#include <stdio.h>
int main(void) { printf("%.6f %.6f\n", gtlab_multibounce_linear(0.0f, 0.5f), gtlab_multibounce_linear(1.0f, 0.5f)); return 0; }
C
if cc -std=c11 -Wall -Werror -I"$work" "$work/use_header.c" -o "$work/use_header" 2>"$work/cc.log"; then
  read -r at0 at1 < <("$work/use_header")
  [ "$at0" = "0.000000" ] || fail "header function at V_d = 0 gives $at0"
  python3 -c "import sys; sys.exit(0 if abs($at1 - 1.0) < 0.05 else 1)" || fail "header function at V_d = 1 gives $at1"
else
  fail "fit.h does not compile: $(cat "$work/cc.log")"
fi
grep -q "float3 GTAOMultiBounce(float visibility, float3 albedo)" "$work/fit.hlsl" || fail "fit.hlsl lacks GTAOMultiBounce"
expect_shader_compiles mb-hlsl "$work/fit.hlsl" hlsl "float4(GTAOMultiBounce(v.x, v.yzw), 1.0)"
expect_shader_compiles mb-glsl "$work/fit.glsl" glsl "vec4(GTAOMultiBounce(v.x, v.yzw), 1.0)"
no_leftovers "$work"
finish
