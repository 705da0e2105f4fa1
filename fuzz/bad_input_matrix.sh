#!/bin/bash
# Regenerates the table of docs/bad-input.md: runs `aokit render` on bad inputs and prints one
# markdown row per case (input, command, exit code, stderr). Each run is limited to 60 s and
# 8 GiB of address space. Usage (from the repository root, after `cargo build --release`):
#     fuzz/bad_input_matrix.sh [path/to/aokit] > /tmp/rows.md
set -u
AOKIT=$(realpath "${1:-target/release/aokit}")
SEEDS=$(realpath fuzz/seeds)
W=$(mktemp -d /tmp/aokit-bad-input.XXXXXX)
cd "$W" || exit 1
SMALL="--width 64 --height 48 --guard 8"
PLY_XYZ=$'property float x\nproperty float y\nproperty float z\n'
FACE=$'element face 1\nproperty list uchar int vertex_indices\n'
TRI_BIN=AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA  # three f32 vertices, base64

# A one-triangle glTF: $1 = buffer URI, $2 = POSITION accessor count, $3 = extra top-level JSON
gltf() {
  printf '{"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0%s}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"buffers":[{"byteLength":36,"uri":"%s"}],"bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,"type":"VEC3","count":%s,"min":[0,0,0],"max":[1,1,0]}]}' "${3:-}" "$1" "${2:-3}"
}

row() { # row DESCRIPTION ARGS...
  local desc=$1; shift
  local out rc lines
  out=$( (ulimit -v 8388608; timeout 60 "$AOKIT" render "$@" 2>&1 >/dev/null) )
  rc=$?
  lines=$(printf '%s' "$out" | grep -c '')
  [ "$rc" = 124 ] && out="(timed out after 60 s)"
  local shown
  shown=$(printf '%s' "$out" | grep -v '^\s*$' | head -1 | sed "s#$W/##g; s#|#\\\\|#g")
  [ "$lines" -gt 1 ] && shown="$shown ⏎ (+$((lines - 1)) more lines)"
  [ -z "$out" ] && shown="(none: rendered)"
  printf '| %s | `aokit render %s` | %s | %s |\n' "$desc" "$(echo "$*" | sed "s#$W/##g; s#$SMALL##; s#  # #g; s/ *\$//")" "$rc" "$shown"
}

# ---- scene files -----------------------------------------------------------------------------
printf 'v 0 0 0\nv 1 0 0\nf 1 2 7\n' > bad_index.obj
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2147483648\n' > index_2_31.obj
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -9\n' > index_relative.obj
printf 'v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > nan.obj
printf 'v 1e39 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > inf.obj
printf 'v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n' > zero_area.obj
printf 'mtllib kd.mtl\nusemtl m\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > short_kd.obj
printf 'newmtl m\nKd 0.5\n' > kd.mtl
printf 'mtllib /dev/zero\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > dev_zero_mtl.obj
: > empty.obj; : > empty.ply; : > empty.gltf
mkdir -p folder.obj
printf 'solid x\nendsolid x\n' > model.stl

head -c 1500 "$SEEDS/gltf/cornell.gltf" > truncated.gltf
head -c 1200 "$SEEDS/gltf/cornell.glb" > truncated.glb
printf 'glTF\002\000\000\000\004\000\000\000' > short_header.glb
gltf missing.bin > missing_buffer.gltf
gltf file:///dev/zero > dev_zero_buffer.gltf
gltf "data:application/octet-stream;base64,$TRI_BIN" 1000000000 > count_1e9.gltf
gltf "data:application/octet-stream;base64,$TRI_BIN" 3 ',"children":[0]' > cycle.gltf

# An alpha-masked material whose image sits in a buffer view without a mimeType.
printf '{"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0}]}],"materials":[{"alphaMode":"MASK","pbrMetallicRoughness":{"baseColorTexture":{"index":0}}}],"textures":[{"source":0}],"images":[{"bufferView":0}],"buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,%s"}],"bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,"type":"VEC3","count":3,"min":[0,0,0],"max":[1,1,0]}]}' "$TRI_BIN" > image_no_mime.gltf
cp "$SEEDS/ply/cornell_ascii.ply" fake.ply.gz
head -c 300 "$SEEDS/ply_gz/cornell_le.ply.gz" > truncated.ply.gz
head -c 900 "$SEEDS/ply/cornell_le.ply" > truncated.ply
head -c 1500 "$SEEDS/ply/cornell_ascii.ply" > truncated_ascii.ply
printf 'ply\nformat ascii 1.0\nelement vertex 10000000000\n%s%send_header\n0 0 0\n' "$PLY_XYZ" "$FACE" > huge_header.ply
printf 'ply\nformat binary_little_endian 1.0\nelement vertex 3\n%selement face 10000000\nproperty list uchar int vertex_indices\nend_header\n' "$PLY_XYZ" > ten_million_faces.ply
head -c 64 /dev/zero >> ten_million_faces.ply
printf 'ply\nformat ascii 1.0\nelement vertex 18446744073709551616\n%s%send_header\n' "$PLY_XYZ" "$FACE" > u64_header.ply
printf 'ply\nformat ascii 1.0\nelement vertex 3\n%s%send_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n' "$PLY_XYZ" "$FACE" > bad_face.ply
printf 'ply\nformat ascii 1.0\nelement vertex 3\n%s%send_header\nnan 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' "$PLY_XYZ" "$FACE" > nan.ply

row "OBJ face index beyond the vertices" --scene bad_index.obj $SMALL
row "OBJ face index 2³¹" --scene index_2_31.obj $SMALL
row "OBJ relative index before the first vertex" --scene index_relative.obj $SMALL
row "OBJ NaN vertex" --scene nan.obj $SMALL
row "OBJ vertex overflowing f32 (1e39 = inf)" --scene inf.obj $SMALL
row "OBJ with only a zero-area triangle" --scene zero_area.obj $SMALL
row "MTL with a short colour line (\`Kd 0.5\`)" --scene short_kd.obj $SMALL --out short_kd.png
row "OBJ whose mtllib is /dev/zero" --scene dev_zero_mtl.obj $SMALL --out dev_zero_mtl.png
row "empty .obj" --scene empty.obj $SMALL
row "empty .ply" --scene empty.ply $SMALL
row "empty .gltf" --scene empty.gltf $SMALL
row "directory named .obj" --scene folder.obj $SMALL
row "unsupported extension" --scene model.stl $SMALL
row "file does not exist" --scene nowhere.obj $SMALL
row "truncated .gltf (JSON cut)" --scene truncated.gltf $SMALL
row "truncated .glb" --scene truncated.glb $SMALL
row "GLB header length < 12" --scene short_header.glb $SMALL
row "glTF buffer file missing" --scene missing_buffer.gltf $SMALL
row "glTF buffer URI /dev/zero" --scene dev_zero_buffer.gltf $SMALL
row "glTF accessor count 10⁹" --scene count_1e9.gltf $SMALL
row "glTF image in a buffer view without mimeType" --scene image_no_mime.gltf $SMALL
row "glTF node that is its own child" --scene cycle.gltf $SMALL
row "plain PLY named .ply.gz (fake gzip)" --scene fake.ply.gz $SMALL
row "truncated .ply.gz" --scene truncated.ply.gz $SMALL
row "truncated binary PLY" --scene truncated.ply $SMALL
row "truncated ascii PLY" --scene truncated_ascii.ply $SMALL
row "PLY header \`element vertex 10000000000\`" --scene huge_header.ply $SMALL
row "PLY header claiming 10⁷ faces" --scene ten_million_faces.ply $SMALL
row "PLY header count beyond u64" --scene u64_header.ply $SMALL
row "PLY face index beyond the vertices" --scene bad_face.ply $SMALL
row "PLY ascii \`nan\` coordinate" --scene nan.ply $SMALL
row "neither a built-in scene nor a file" --scene nope $SMALL

# ---- sizes and camera ------------------------------------------------------------------------
row "zero width" --scene cornell --width 0 --height 48
row "huge size" --scene cornell --width 100000 --height 100000
row "guard band beyond the limit" --scene cornell --width 64 --height 48 --guard 10000
row "guard band 2³¹ (wraps the size check)" --scene cornell --width 64 --height 48 --guard 2147483648
row "NaN radius" --scene cornell $SMALL --radius nan
row "negative radius" --scene cornell $SMALL --radius -1
row "zero exponent" --scene cornell $SMALL --exponent 0
row "negative thickness" --scene cornell $SMALL --thickness -1
row "eye = target" --scene cornell $SMALL --eye 1,2,3 --target 1,2,3
row "up parallel to the view direction" --scene cornell $SMALL --eye 0,0,0 --target 0,5,0
row "NaN eye" --scene cornell $SMALL --eye nan,0,0 --target 0,0,1
row "eye without target" --scene cornell $SMALL --eye 0,0,0
row "malformed vector" --scene cornell $SMALL --eye 1,2 --target 0,0,0
row "fov 0" --scene cornell $SMALL --fov 0
row "fov 180" --scene cornell $SMALL --fov 180
row "fov NaN" --scene cornell $SMALL --fov nan
row "unknown camera preset" --scene cornell $SMALL --camera nope
row "camera preset for a file scene" --scene zero_area.obj $SMALL --camera front

# ---- technique and output --------------------------------------------------------------------
row "unknown technique" --scene cornell $SMALL --technique nope
row "unknown technique setting" --scene cornell $SMALL --technique vao:nope=1
row "unwritable output folder" --scene cornell $SMALL --out /nonexistent/ao.png
mkdir -p out.png
row "output path is a directory" --scene cornell $SMALL --out out.png
row "output under /proc" --scene cornell $SMALL --out /proc/ao.png

rm -rf "$W"
