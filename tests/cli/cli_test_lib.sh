# Shared by the CLI tests: run gtlab, check what a user sees.
# Usage: source it with $gtlab and $work set.
passed=0
failed=0

fail() { echo "FAIL: $*" >&2; failed=$((failed + 1)); }
pass() { passed=$((passed + 1)); }

# vulkan_preload: under ASan (GTLAB_VULKAN_PRELOAD set, tests/gpu/CMakeLists.txt)
# $gtlab becomes a wrapper in $work that preloads ASan and the Vulkan driver
# for gtlab alone (bash and python3 are not built with ASan).
vulkan_preload() {
  [ -n "$GTLAB_VULKAN_PRELOAD" ] || return 0
  printf '#!/bin/sh\nLD_PRELOAD="%s" exec "%s" "$@"\n' "$GTLAB_VULKAN_PRELOAD" "$gtlab" >"$work/gtlab"
  chmod +x "$work/gtlab"
  gtlab=$work/gtlab
}

# run ARGS...: runs gtlab, keeping exit status, stdout and stderr.
run() {
  "$gtlab" "$@" >"$work/stdout" 2>"$work/stderr"
  status=$?
}

# no_leftovers DIR: no temporary file was left behind.
no_leftovers() {
  if ls -a "$1" 2>/dev/null | grep -q '\.tmp-'; then
    fail "temporary files left in $1: $(ls -a "$1" | grep '\.tmp-')"
  fi
}

# expect_error NAME PATTERN OUTPUT -- ARGS...: gtlab must exit 1, print exactly
# one error line "gtlab: <...PATTERN...>" on stderr (warnings about the same
# input may come before it), and leave no OUTPUT behind.
expect_error() {
  local name=$1 pattern=$2 output=$3
  shift 4
  rm -f "$output"
  run "$@"
  local lines
  lines=$(grep -vc '^gtlab: warning: ' "$work/stderr")
  if [ "$status" -ne 1 ]; then
    fail "$name: exit status $status, expected 1 (stderr: $(head -c 300 "$work/stderr"))"
  elif [ "$lines" -ne 1 ]; then
    fail "$name: $lines lines on stderr, expected 1: $(head -c 500 "$work/stderr")"
  elif ! grep -q "^gtlab: .*$pattern" "$work/stderr"; then
    fail "$name: stderr does not match 'gtlab: ...$pattern': $(cat "$work/stderr")"
  elif [ -n "$output" ] && [ -e "$output" ]; then
    fail "$name: $output was written"
  else
    pass
  fi
  no_leftovers "$(dirname "${output:-$work/x}")"
}

# expect_ok NAME ARGS...: gtlab must exit 0.
expect_ok() {
  local name=$1
  shift
  run "$@"
  if [ "$status" -ne 0 ]; then
    fail "$name: exit status $status: $(head -c 500 "$work/stderr")"
  else
    pass
  fi
}

# json_is KEY OP VALUE FILE: compares a number of gtlab compare --json output
# (OP is a Python comparison: ==, >, <=, ...).
json_is() {
  python3 -c "import json,sys; v=json.load(open(sys.argv[4]))[sys.argv[1]]; sys.exit(0 if eval(f'{v!r} {sys.argv[2]} {sys.argv[3]}') else 1)" "$1" "$2" "$3" "$4"
}

# expect_shader_compiles NAME FILE LANG CALL: the generated shader functions in
# FILE (LANG glsl or hlsl) compile with Khronos' glslangValidator (Debian's
# glslang-tools, installed by setup.sh) inside a fragment shader whose output
# is CALL, an expression of the input v (a float4/vec4) returning 4 floats.
expect_shader_compiles() {
  local name=$1 file=$2 lang=$3 call=$4 src
  if [ "$lang" = glsl ]; then
    src="$work/$name.frag"
    { echo "#version 450"; cat "$file"
      printf 'layout(location = 0) in vec4 v;\nlayout(location = 0) out vec4 o;\nvoid main() { o = %s; }\n' "$call"; } >"$src"
    glslangValidator "$src" >"$work/$name.log" 2>&1
  else
    src="$work/$name.hlsl"
    { cat "$file"; printf 'float4 main(float4 v : TEXCOORD0) : SV_Target { return %s; }\n' "$call"; } >"$src"
    glslangValidator -D -V -e main -S frag "$src" -o "$work/$name.spv" >"$work/$name.log" 2>&1
  fi
  [ $? -eq 0 ] && pass || fail "$name: $file does not compile as $lang: $(head -c 600 "$work/$name.log")"
}

# The reference types beside ao, each with a small scene and its own
# options (size, spp and seed left to the test): several quantities each.
declare -A other_references=(
  [multibounce]="multibounce --scene builtin:boxes --albedo 0.2,0.8"
  [specular-occlusion]="specular-occlusion --scene builtin:corner --roughness 0.4 --environment sky"
  [sphere-light]="sphere-light --scene builtin:plane --light-position 0,2,-3 --light-radius 0.5"
  [fog]="fog --scene builtin:cornell"
)

finish() {
  echo "$passed passed, $failed failed"
  [ "$failed" -eq 0 ]
}
