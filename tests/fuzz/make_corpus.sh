#!/usr/bin/env bash
# Rebuilds the seed corpus of the fuzz targets (tests/fuzz/corpus/<target>/)
# from gtlab itself and small hand-written files: usage
#   tests/fuzz/make_corpus.sh build/cli/gtlab
# Every seed is small (a few KB at most). The corpus is committed; run this
# only to change it.
set -euo pipefail
gtlab=$(realpath "$1")
here=$(cd "$(dirname "$0")" && pwd)
corpus=$here/corpus
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
rm -rf "$corpus"
mkdir -p "$corpus"/{json,camera,gltf,exr,merge,fit_inputs,shader}

# Renders at 4x4 pixels: every kind of EXR the fits and merge read.
cd "$work"
"$gtlab" render gbuffer --scene builtin:boxes --width 4 --height 4 -o g.exr >/dev/null
"$gtlab" render ao --scene builtin:boxes --width 4 --height 4 --spp 4 -o ao.exr >/dev/null
"$gtlab" render multibounce --scene builtin:corner --albedo 0.2,0.8 --width 4 --height 4 --spp 4 -o mb.exr >/dev/null
"$gtlab" render specular-occlusion --scene builtin:boxes --roughness 0.5 --width 4 --height 4 --spp 4 -o so.exr >/dev/null
oiiotool so.exr ao.exr --chappend -o so_ao.exr
oiiotool g.exr -d half --tile 2 2 -o g_half_tiled.exr
cp g.exr ao.exr mb.exr so.exr g_half_tiled.exr "$corpus/exr/"
cp g.exr mb.exr so_ao.exr "$corpus/fit_inputs/"
cp ao.camera.json "$corpus/camera/written.json"
cp ao.camera.json "$corpus/json/camera.json"

# glTF: a built-in scene as gtlab writes it, and hand-written files.
"$gtlab" scene write plane -o "$corpus/gltf/plane.glb" >/dev/null
# A triangle (three VEC3 floats each), base64 in a data: URI.
triangle=AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA
# A 1x1 RGBA PNG.
png=iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8z8BQDwAEhQGAhKmMIQAAAABJRU5ErkJggg==
cat >"$corpus/gltf/triangle.gltf" <<JSON
{"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
 "nodes":[{"children":[1],"translation":[1,0,0]},{"mesh":0,"rotation":[0,0,0.7071068,0.7071068],"scale":[2,2,2]}],
 "meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1,"material":0}]}],
 "materials":[{"pbrMetallicRoughness":{"baseColorFactor":[0.5,0.5,0.5,1],"baseColorTexture":{"index":0}}}],
 "textures":[{"source":0}],"images":[{"uri":"data:image/png;base64,$png"}],
 "buffers":[{"byteLength":42,"uri":"data:application/octet-stream;base64,${triangle}AAABAAIA"}],
 "bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6}],
 "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},
              {"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}]}
JSON
cat >"$corpus/gltf/camera-matrix.gltf" <<JSON
{"asset":{"version":"2.0"},"extensionsUsed":["KHR_materials_unlit"],
 "nodes":[{"camera":0,"matrix":[1,0,0,0,0,1,0,0,0,0,1,0,0,1,5,1]},{"mesh":0}],
 "cameras":[{"type":"perspective","perspective":{"yfov":0.8,"aspectRatio":1.5,"znear":0.1}}],
 "meshes":[{"primitives":[{"attributes":{"POSITION":0,"NORMAL":0,"TEXCOORD_0":1},"mode":4}]}],
 "buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,$triangle"}],
 "bufferViews":[{"buffer":0,"byteLength":36,"byteStride":12}],
 "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},
              {"bufferView":0,"componentType":5126,"count":3,"type":"VEC2"}]}
JSON
cp "$corpus/gltf/triangle.gltf" "$corpus/json/gltf.json"
# A GLB whose BIN chunk holds the triangle, its indices and the PNG texture.
python3 - "$corpus/gltf/textured.glb" "$triangle" "$png" <<'PY'
import base64, json, struct, sys
positions, png = base64.b64decode(sys.argv[2]), base64.b64decode(sys.argv[3])
texcoords = struct.pack("<6f", 0, 0, 1, 0, 0, 1)
indices = struct.pack("<3H", 0, 1, 2) + b"\0\0"
bin_ = positions + texcoords + indices + png
bin_ += b"\0" * (-len(bin_) % 4)
offsets = [0, 36, 60, 68]
doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
       "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}]}],
       "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0},
                                               "metallicRoughnessTexture": {"index": 0}}}],
       "textures": [{"source": 0}], "images": [{"bufferView": 3, "mimeType": "image/png"}],
       "buffers": [{"byteLength": len(bin_)}],
       "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 24},
                       {"buffer": 0, "byteOffset": 60, "byteLength": 6}, {"buffer": 0, "byteOffset": 68, "byteLength": len(png)}],
       "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                     {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"},
                     {"bufferView": 2, "componentType": 5123, "count": 3, "type": "SCALAR"}]}
text = json.dumps(doc, separators=(",", ":")).encode()
text += b" " * (-len(text) % 4)
glb = struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(text) + 8 + len(bin_))
glb += struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(bin_), 0x004E4942) + bin_
open(sys.argv[1], "wb").write(glb)
PY

# Issue 30: what real pipelines write. gltfpack's quantized (default) and
# meshopt-compressed (-c, with a fallback buffer without data) forms of the
# plane; one Draco primitive of assimp-testmodels' 2CylinderEngine in a GLB
# of its own; and hand-written strip, fan, sparse, morph and skin files.
gltfpack -i "$corpus/gltf/plane.glb" -o "$corpus/gltf/plane-quantized.glb" >/dev/null
gltfpack -i "$corpus/gltf/plane.glb" -o "$corpus/gltf/plane-meshopt.glb" -c >/dev/null
python3 - "$corpus/gltf/draco.glb" /usr/share/assimp/models/glTF2/draco/2CylinderEngine.gltf <<'PY'
import json, os, struct, sys
src = json.load(open(sys.argv[2]))
data = open(os.path.join(os.path.dirname(sys.argv[2]), src["buffers"][0]["uri"]), "rb").read()
def draco_view(p):
    return src["bufferViews"][p["extensions"]["KHR_draco_mesh_compression"]["bufferView"]]
prim = min((p for m in src["meshes"] for p in m["primitives"]), key=lambda p: draco_view(p)["byteLength"])
view = draco_view(prim)
bin_ = data[view.get("byteOffset", 0):view.get("byteOffset", 0) + view["byteLength"]]
bin_ += b"\0" * (-len(bin_) % 4)
ext = dict(prim["extensions"]["KHR_draco_mesh_compression"], bufferView=0)
names = sorted(ext["attributes"])
accessors = [{k: v for k, v in src["accessors"][prim["attributes"][n]].items() if k != "bufferView"} for n in names]
accessors.append({k: v for k, v in src["accessors"][prim["indices"]].items() if k != "bufferView"})
doc = {"asset": {"version": "2.0"}, "extensionsUsed": ["KHR_draco_mesh_compression"],
       "extensionsRequired": ["KHR_draco_mesh_compression"], "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
       "meshes": [{"primitives": [{"attributes": {n: i for i, n in enumerate(names)}, "indices": len(names),
                                   "extensions": {"KHR_draco_mesh_compression": ext}}]}],
       "accessors": accessors, "bufferViews": [{"buffer": 0, "byteLength": view["byteLength"]}],
       "buffers": [{"byteLength": len(bin_)}]}
text = json.dumps(doc, separators=(",", ":")).encode()
text += b" " * (-len(text) % 4)
glb = struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(text) + 8 + len(bin_))
glb += struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(bin_), 0x004E4942) + bin_
open(sys.argv[1], "wb").write(glb)
PY
# Four vertices (a unit square, z = 0), then indices 0 1 2 3, a joint set
# (0 0 0 0) and a weight set (1 0 0 0) per vertex, and an identity matrix.
square=AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAACAPwAAgD8AAAAAAAABAAIAAwA=
cat >"$corpus/gltf/strip-sparse.gltf" <<JSON
{"asset":{"version":"2.0"},"nodes":[{"mesh":0},{"mesh":1,"translation":[2,0,0]}],
 "meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1,"mode":5}]},
           {"primitives":[{"attributes":{"POSITION":2},"mode":6}]}],
 "buffers":[{"byteLength":56,"uri":"data:application/octet-stream;base64,$square"}],
 "bufferViews":[{"buffer":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":8}],
 "accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3"},
              {"bufferView":1,"componentType":5123,"count":4,"type":"SCALAR"},
              {"bufferView":0,"componentType":5126,"count":4,"type":"VEC3",
               "sparse":{"count":1,"indices":{"bufferView":1,"byteOffset":6,"componentType":5123},"values":{"bufferView":0}}}]}
JSON
cat >"$corpus/gltf/morph-skin.gltf" <<JSON
{"asset":{"version":"2.0"},"scenes":[{"nodes":[0,1,2]}],
 "nodes":[{"mesh":0,"weights":[0.5]},{"mesh":1,"skin":0},{"rotation":[0,0,0.7071068,0.7071068]}],
 "skins":[{"joints":[2]}],
 "meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1,"mode":5,"targets":[{"POSITION":0}]}],"weights":[1]},
           {"primitives":[{"attributes":{"POSITION":0,"JOINTS_0":2,"WEIGHTS_0":3},"indices":1,"mode":5}]}],
 "buffers":[{"byteLength":56,"uri":"data:application/octet-stream;base64,$square"}],
 "bufferViews":[{"buffer":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":8}],
 "accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3"},
              {"bufferView":1,"componentType":5123,"count":4,"type":"SCALAR"},
              {"componentType":5121,"count":4,"type":"VEC4",
               "sparse":{"count":1,"indices":{"bufferView":1,"componentType":5123},"values":{"bufferView":0}}},
              {"componentType":5126,"count":4,"type":"VEC4",
               "sparse":{"count":1,"indices":{"bufferView":1,"componentType":5123},"values":{"bufferView":0}}}]}
JSON

# JSON and camera JSON written by hand.
printf '{"position":[0,1,5],"target":[0,0,0],"up":[0,1,0],"yfov_deg":45,"width":64,"height":48}' >"$corpus/camera/full.json"
printf '\xef\xbb\xbf{"position":[1e1,-2.5E-1,0.0],"target":[0,0,0],"yfov_deg":30.5,"width":1,"height":65536}\n' >"$corpus/camera/bom.json"
printf '[true,false,null,-0,1.5e300,"\\u00e9\\ud83d\\ude00\\n",{"a":{"b":[[]]}}]' >"$corpus/json/values.json"
printf '{"k\xc3\xa9y":"\xe2\x82\xac\xf0\x9f\x98\x80","":[ 1 , 2 ]}\r\n' >"$corpus/json/utf8.json"

# Merge edits (fuzz_merge.c).
printf '' >"$corpus/merge/unchanged.txt"
printf 'gtlab.sample_blocks=7:0+2 9:2+2\n--\ngtlab.sample_blocks=7:4+4\n' >"$corpus/merge/blocks.txt"
printf -- '--\ngtlab.sample_blocks=7:2+4\n' >"$corpus/merge/overlap.txt"
printf -- '-gtlab.scale_exponents\n--\n!spp.N\n' >"$corpus/merge/missing.txt"
printf -- '@spp.N=3:1e9\n@ao.V.sum=0:nan\n--\ngtlab.scale_exponents=ao.V:99 bent.X:-3\ngtlab.quantity=gbuffer\n' >"$corpus/merge/values.txt"
printf -- 'gtlab.sample_blocks=4294967295:18446744073709551615+18446744073709551615 1:2+3\n' >"$corpus/merge/huge.txt"
# Shaders (fuzz_shader.c): the project's GTAO in both languages (the HLSL
# includes gtao.inc), small valid and broken ones, and the family of issue
# 41's crash that does not crash (a main without its body: no entry point).
# The members that crashed glslang are in regressions/shader/.
cp "$here/../../techniques/gtao/gtao.glsl" "$here/../../techniques/gtao/gtao.hlsl" "$corpus/shader/"
printf 'RWStructuredBuffer<float> o : register(u0);\n[numthreads(8, 1, 1)]\nvoid main(uint3 id : SV_DispatchThreadID)\n{\n    o[id.x] = 2.0 * id.x;\n}\n' >"$corpus/shader/small.hlsl"
printf '#version 450\nlayout(local_size_x = 8) in;\nlayout(std430, binding = 0) buffer O { float o[]; };\nvoid main() { o[gl_GlobalInvocationID.x] = 1.0; }\n' >"$corpus/shader/small.glsl"
printf '#version 450\nlayout(local_size_x = 8) in;\nvoid main() { undeclared = 1; }\n' >"$corpus/shader/broken.glsl"
printf '#include "nowhere.inc"\n[numthreads(1, 1, 1)]\nvoid main() {}\n' >"$corpus/shader/include-missing.hlsl"
printf '// gtlab.output ao.V\nRWStructuredBuffer<float> o : register(u0);\n[numthreads(8, 8, 1)]\nvoid main()\n' >"$corpus/shader/main-without-body.hlsl"
printf 'RWStructuredBuffer<float> o;\nvoid main(uint x) x;\n' >"$corpus/shader/header-then-parameter.hlsl"
ls -la "$corpus"/*
