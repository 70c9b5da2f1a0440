#!/bin/bash
# The GGX LTC table's writers (ltc/ltc_ggx_writers.c): two generations are
# byte-identical, the EXR round-trips bit for bit (in ltc_ggx_emit), the C
# header compiles as C11, the HLSL and GLSL compile with glslangValidator, no
# temporary file is left.
emit=$1
work=$2
rm -rf "$work" && mkdir -p "$work/a" "$work/b"
source "$(dirname "$0")/../../../tests/cli/cli_test_lib.sh"

"$emit" "$work/a" && pass || fail "first generation"
"$emit" "$work/b" >/dev/null && pass || fail "second generation"
for f in ltc.exr ltc.h ltc.hlsl ltc.glsl; do
  cmp -s "$work/a/$f" "$work/b/$f" && pass || fail "$f differs between two generations"
done
printf '#include "%s"\nfloat ltc_at(int i) { return LTC_GGX[i %% (LTC_GGX_SIZE * LTC_GGX_SIZE * 6)]; }\n' "$work/a/ltc.h" >"$work/use_header.c"
cc -std=c11 -Wall -Wextra -Werror -c "$work/use_header.c" -o "$work/use_header.o" && pass || fail "ltc.h does not compile"
if command -v glslangValidator >/dev/null; then
  expect_shader_compiles ltc-hlsl "$work/a/ltc.hlsl" hlsl "LTC_INVERSE_M(v.x, v.y) + LTC_MAGNITUDE_FRESNEL(v.x, v.y)"
  expect_shader_compiles ltc-glsl "$work/a/ltc.glsl" glsl "LTC_INVERSE_M(v.x, v.y) + LTC_MAGNITUDE_FRESNEL(v.x, v.y)"
fi
no_leftovers "$work/a"
finish
