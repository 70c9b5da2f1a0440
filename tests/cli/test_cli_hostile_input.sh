#!/usr/bin/env bash
# Crafted input (issue 21): the two inputs that overflowed the stack, and
# messages that quoted unbounded input or spoke a parser's words. Each is
# generated here; each must give one short line "gtlab: <file>: <problem>"
# in gtlab's words, exit status 1, and write nothing.
gtlab=$1
work=$2
rm -rf "$work" && mkdir -p "$work"
source "$(dirname "$0")/cli_test_lib.sh"
out=$work/out.exr
render_gbuffer() { echo render gbuffer --scene "$1" --width 16 --height 16 -o "$out"; }

# last_line_at_most N: the error line is at most N characters long.
last_line_at_most() {
  local length
  length=$(tail -1 "$work/stderr" | wc -c)
  [ "$length" -le "$1" ] && pass || fail "error line of $length characters (at most $1): $(head -c 300 "$work/stderr")"
}

# 1. 100,000 nested arrays in a .gltf (recursive JSON parsers overflowed the
# stack); the 257th level opens at column 37 + 255 = 292.
deep_json() { # $1 = levels
  printf '{"asset":{"version":"2.0"},"extras":'
  head -c "$1" /dev/zero | tr '\0' '['
  head -c "$1" /dev/zero | tr '\0' ']'
  printf '}'
}
deep_json 100000 >"$work/deep.gltf"
expect_error deep-gltf "deep.gltf: JSON nests deeper than 256 arrays and objects at line 1, column 292$" "$out" -- $(render_gbuffer "$work/deep.gltf")
[ -e "$work/out.camera.json" ] && fail "deep-gltf: out.camera.json was written"
# The same JSON as the JSON chunk of a GLB.
python3 - "$work/deep.gltf" "$work/deep.glb" <<'PY'
import struct, sys
text = open(sys.argv[1], "rb").read()
text += b" " * (-len(text) % 4)
open(sys.argv[2], "wb").write(struct.pack("<4sII", b"glTF", 2, 20 + len(text)) + struct.pack("<II", len(text), 0x4E4F534A) + text)
PY
expect_error deep-glb "deep.glb: JSON nests deeper than 256 arrays and objects at line 1, column 292$" "$out" -- $(render_gbuffer "$work/deep.glb")
# And as camera JSON.
{ printf '{"position":'; head -c 60000 /dev/zero | tr "\0" "["; } >"$work/cam-deep.json"
expect_error deep-camera "cam-deep.json: JSON nests deeper than 256 arrays and objects at line 1, column 268$" "$out" -- render ao --scene builtin:plane --camera "$work/cam-deep.json" -o "$out"
# 256 levels are read (and the file then refused for what it is: no scene).
deep_json 255 >"$work/deep-ok.gltf"
expect_error deep-255 "deep-ok.gltf: .*no triangles" "$out" -- $(render_gbuffer "$work/deep-ok.gltf")

# 2. gtlab merge on a render whose gtlab.sample_blocks is 53 KB of blocks
# with offsets and counts near 2^64 (it overflowed a stack buffer).
expect_ok small-render render ao --scene builtin:plane --width 4 --height 4 --spp 4 -o "$work/a.exr"
blocks=$(for i in $(seq 1 1024); do printf '4294967295:18446744073709551615+18446744073709551615 '; done)
[ ${#blocks} -gt 53000 ] || fail "crafted attribute of ${#blocks} characters only"
oiiotool "$work/a.exr" --sattrib gtlab.sample_blocks "$blocks" -o "$work/crafted.exr" || fail "oiiotool"
expect_error crafted-blocks "crafted.exr: header attribute gtlab.sample_blocks: block 1 ('4294967295:18446744073709551615+18446744073709551615') ends past sample 2\^32 (sample indices are 32-bit)$" "$work/merged.exr" -- merge "$work/a.exr" "$work/crafted.exr" -o "$work/merged.exr"
expect_error crafted-blocks-first "crafted.exr: header attribute gtlab.sample_blocks: block 1" "$work/merged.exr" -- merge "$work/crafted.exr" "$work/a.exr" -o "$work/merged.exr"
# More blocks than a merge holds, each valid.
blocks=$(for i in $(seq 0 1024); do printf '1:%d+1 ' "$i"; done)
oiiotool "$work/a.exr" --sattrib gtlab.sample_blocks "$blocks" -o "$work/many.exr" || fail "oiiotool"
expect_error many-blocks "many.exr: header attribute gtlab.sample_blocks: more than 1024 blocks$" "$work/merged.exr" -- merge "$work/a.exr" "$work/many.exr" -o "$work/merged.exr"
# A 2,000-digit block is quoted cut to 80 characters.
oiiotool "$work/a.exr" --sattrib gtlab.sample_blocks "$(head -c 2000 /dev/zero | tr '\0' '7')" -o "$work/long.exr" || fail "oiiotool"
expect_error long-block "long.exr: header attribute gtlab.sample_blocks: block 1 ('7\{80\}\.\.\.') is not seed:offset+count" "$work/merged.exr" -- merge "$work/a.exr" "$work/long.exr" -o "$work/merged.exr"
last_line_at_most 300

# 3. Messages in gtlab's words: invalid UTF-8 in a string at column 631
# (nlohmann json said "[json.exception.parse_error.101] ... ill-formed UTF-8 byte").
{ printf '{"asset":{"version":"2.0"},"extras":"'; head -c 593 /dev/zero | tr '\0' 'a'; printf '\xff"}'; } >"$work/utf8.gltf"
expect_error bad-utf8 "utf8.gltf: invalid UTF-8 in a JSON string at line 1, column 631$" "$out" -- $(render_gbuffer "$work/utf8.gltf")
# A file requiring an extension gtlab does not read names it, before any
# other error: the Draco file with its extension renamed (tinygltf alone would
# say "accessor[0] invalid bufferView").
draco=/usr/share/assimp/models/glTF2/draco
if [ -e "$draco/2CylinderEngine.gltf" ]; then
  cp "$draco"/* "$work/"
  sed 's/KHR_draco_mesh_compression/KHR_draco_mesh_compression_v9/g' "$draco/2CylinderEngine.gltf" >"$work/renamed.gltf"
  expect_error unknown-extension "renamed.gltf: requires the glTF extension KHR_draco_mesh_compression_v9, which gtlab does not support$" "$out" -- $(render_gbuffer "$work/renamed.gltf")
fi
# A 2,000-character accessor type is quoted cut to 80 characters.
type=$(head -c 2000 /dev/zero | tr '\0' 'Q')
cat >"$work/long-type.gltf" <<JSON
{"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
 "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
 "buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
 "bufferViews":[{"buffer":0,"byteLength":36}],
 "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"$type"}]}
JSON
expect_error long-type "long-type.gltf: cannot load glTF: .*\"Q\{80\}\.\.\.\"" "$out" -- $(render_gbuffer "$work/long-type.gltf")
last_line_at_most 300
finish
