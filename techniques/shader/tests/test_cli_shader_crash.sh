#!/usr/bin/env bash
# Shaders that crash the compiler (issue 41, defect 1): an HLSL function
# header without its { } body followed by a global's name is a null read in
# glslang (TParseContextBase::growGlobalUniformBlock). gtlab compiles in a
# child process (core/isolated_call.h), so each member of the family gives
# one line naming the file and exit 1 on every path that compiles a user's
# shader: shader run, bench shader, shader score --function, and gtlab all
# through a project's screen_shaders; nothing is written. A main that is
# only a header (glslang then makes an empty entry point, a shader that
# writes nothing) is refused too. The shapes are tests/fuzz/regressions/
# shader/ (crash-*) and corpus/shader/main-without-body.hlsl.
gtlab=$1
work=$2
source_dir=$3
rm -rf "$work" && mkdir -p "$work"
source "$(dirname "$0")/../../../tests/cli/cli_test_lib.sh"
vulkan_preload
"$gtlab" render gbuffer --scene builtin:boxes --width 16 --height 16 -o "$work/g.exr" >/dev/null 2>&1 || fail "gbuffer"
"$gtlab" render multibounce --scene builtin:corner --albedo 0.2,0.8 --width 16 --height 16 --spp 4 \
  -o "$work/mb.exr" >/dev/null 2>&1 || fail "render multibounce"
crashed="the shader compiler died on this source (glslang, signal 11"

# A screen shader of the contract (docs/shaders.md) around each crashing shape.
for shape in "$source_dir"/tests/fuzz/regressions/shader/crash-*.hlsl; do
  name=$(basename "$shape" .hlsl)
  { echo "// gtlab.output ao.V"; cat "$shape"; } >"$work/$name.hlsl"
  expect_error "$name: shader run" "$name.hlsl: $crashed" "$work/o.exr" -- \
    shader run --shader "$work/$name.hlsl" --gbuffer "$work/g.exr" -o "$work/o.exr"
  expect_error "$name: bench shader" "$name.hlsl: $crashed" "" -- \
    bench shader --shader "$work/$name.hlsl" --width 16 --height 16 --frames 1
  printf '{"scenes": [{"path": "builtin:boxes"}], "screen_shaders": [{"path": "%s"}]}' "$name.hlsl" \
    >"$work/$name.json"
  expect_error "$name: all --project" "$name.json: screen_shaders\[0\].path: .*$name.hlsl: $crashed" "$work/out" -- \
    all --project "$work/$name.json" --stages screen-shaders -o "$work/out"
done

# A function file (docs/shaders.md) with the same shape: its header, no body.
printf 'RWStructuredBuffer<float> o : register(u3);\nfloat gtlab_multibounce(float visibility, float albedo) o[0] = 1;\n' \
  >"$work/function.hlsl"
expect_error "function: shader score" "function.hlsl: $crashed" "" -- \
  shader score --function "$work/function.hlsl" "$work/mb.exr"

# main declared, never defined: no entry point, refused in words.
cp "$source_dir/tests/fuzz/corpus/shader/main-without-body.hlsl" "$work/"
expect_error "main without body" "main-without-body.hlsl: no function main with a body" "$work/o.exr" -- \
  shader run --shader "$work/main-without-body.hlsl" --gbuffer "$work/g.exr" -o "$work/o.exr"

# The child still resolves #include beside the file: the project's GTAO, whose HLSL includes gtao.inc.
cp "$source_dir/techniques/gtao/gtao.hlsl" "$source_dir/techniques/gtao/gtao.inc" "$work/"
expect_ok "gtao.hlsl" shader run --shader "$work/gtao.hlsl" --gbuffer "$work/g.exr" -o "$work/o.exr"
[ -s "$work/o.exr" ] && pass || fail "gtao.hlsl wrote no output"
no_leftovers "$work"
finish
