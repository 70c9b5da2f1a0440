#!/bin/bash
# The atmosphere LUTs' writers (atmosphere/atmosphere_luts_writers.c): two
# generations are byte-identical, the EXRs round-trip bit for bit (in
# atmosphere_luts_emit), the C header compiles as C11, the HLSL and GLSL
# compile with glslangValidator, no temporary file is left.
emit=$1
work=$2
rm -rf "$work" && mkdir -p "$work/a" "$work/b"
source "$(dirname "$0")/../../../tests/cli/cli_test_lib.sh"

"$emit" "$work/a" && pass || fail "first generation"
"$emit" "$work/b" >/dev/null && pass || fail "second generation"
for f in atmosphere_inscatter.exr atmosphere_sun.exr atmosphere_sky.exr atmosphere_luts.h atmosphere_luts.hlsl atmosphere_luts.glsl; do
  cmp -s "$work/a/$f" "$work/b/$f" && pass || fail "$f differs between two generations"
done
printf '#include "%s"\nfloat at(int i) { return ATMOSPHERE_INSCATTER[i %% 360] + ATMOSPHERE_SUN[i %% 48] + ATMOSPHERE_SKY[i %% 18]; }\n' \
  "$work/a/atmosphere_luts.h" >"$work/use_header.c"
cc -std=c11 -Wall -Wextra -Werror -c "$work/use_header.c" -o "$work/use_header.o" && pass || fail "atmosphere_luts.h does not compile"
if command -v glslangValidator >/dev/null; then
  expect_shader_compiles atmo-hlsl "$work/a/atmosphere_luts.hlsl" hlsl \
    "float4(AtmosphereInscatterRayleigh(v.x, v.y, v.z, v.w) + AtmosphereInscatterMie(v.x, v.y, v.z, v.w) + AtmosphereSun(v.x, v.z, v.w) + AtmosphereSky(v.x, v.z, v.w), 1.0)"
  expect_shader_compiles atmo-glsl "$work/a/atmosphere_luts.glsl" glsl \
    "vec4(AtmosphereInscatterRayleigh(v.x, v.y, v.z, v.w) + AtmosphereInscatterMie(v.x, v.y, v.z, v.w) + AtmosphereSun(v.x, v.z, v.w) + AtmosphereSky(v.x, v.z, v.w), 1.0)"
fi
no_leftovers "$work/a"
finish
