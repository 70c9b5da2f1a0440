#!/bin/bash
# The DFG LUT's writers (dfg/dfg_lut_writers.c): two generations are
# byte-identical, the EXR round-trips bit for bit (in dfg_lut_emit), the C
# header compiles as C11, the HLSL and GLSL compile with glslangValidator (through
# the CLI tests' helper), no temporary file is left.
emit=$1
work=$2
rm -rf "$work" && mkdir -p "$work/a" "$work/b"
source "$(dirname "$0")/../../../tests/cli/cli_test_lib.sh"

"$emit" "$work/a" && pass || fail "first generation"
"$emit" "$work/b" >/dev/null && pass || fail "second generation"
for f in dfg.exr dfg.png dfg.h dfg.hlsl dfg.glsl; do
  cmp -s "$work/a/$f" "$work/b/$f" && pass || fail "$f differs between two generations"
done
printf '#include "%s"\nfloat dfg_at(int i) { return DFG_LUT[i %% (DFG_LUT_SIZE * DFG_LUT_SIZE * 3)]; }\n' "$work/a/dfg.h" >"$work/use_header.c"
cc -std=c11 -Wall -Wextra -Werror -c "$work/use_header.c" -o "$work/use_header.o" && pass || fail "dfg.h does not compile"
python3 - "$work/a/dfg.png" <<'PY' && pass || fail "dfg.png is not a 32x32 16-bit RGB PNG"
import struct, sys
d = open(sys.argv[1], 'rb').read()
assert d[:8] == b'\x89PNG\r\n\x1a\n'
w, h, depth, colour = struct.unpack('>IIBB', d[16:26])
assert (w, h, depth, colour) == (32, 32, 16, 2), (w, h, depth, colour)
PY
if command -v glslangValidator >/dev/null; then
  expect_shader_compiles dfg-hlsl "$work/a/dfg.hlsl" hlsl "float4(DFG(v.x, v.y), 1.0)"
  expect_shader_compiles dfg-glsl "$work/a/dfg.glsl" glsl "vec4(DFG(v.x, v.y), 1.0)"
fi
no_leftovers "$work/a"
finish
