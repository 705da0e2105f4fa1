#!/usr/bin/env python3
"""Builds the fuzz seeds under fuzz/seeds/<target>/ from aokit's real scenes (the committed
Cornell box, and the Sponza, kitchen and oak tree fetched by `aokit scenes`/the tests into
~/.cache/aokit), cut small: the first hundreds of elements of the big OBJs, the Cornell box
converted to PLY (ascii, binary little/big endian, gzip) and to glTF/GLB, the oak tree as GLB and
as .gltf with data URIs (its leaf texture shrunk to 8x8). Run from the repository root:
    python3 fuzz/seeds/make_seeds.py
"""
import base64, gzip, io, json, os, struct, sys
from PIL import Image

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CACHE = os.environ.get("AOKIT_CACHE") or os.path.join(os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache"), "aokit")
SCENES = os.path.join(CACHE, "scenes")
OUT = os.path.join(ROOT, "fuzz", "seeds")
SEP = b"\0MTL\0"


def write(target, name, data):
    os.makedirs(os.path.join(OUT, target), exist_ok=True)
    with open(os.path.join(OUT, target, name), "wb") as f:
        f.write(data)


def small_obj(path, keep):
    """The first `keep` v/vt/vn and every face that uses only those, with the o/g/usemtl/mtllib lines."""
    out, counts = [], {"v": 0, "vt": 0, "vn": 0}
    for line in open(path, encoding="utf-8", errors="replace"):
        w = line.split()
        if not w:
            continue
        if w[0] in counts:
            counts[w[0]] += 1
            if counts[w[0]] <= keep:
                out.append(line)
        elif w[0] == "f":
            ok = all(0 < int(p) <= keep for t in w[1:] for p in t.split("/") if p)
            if ok:
                out.append(line)
        elif w[0] in ("o", "g", "usemtl", "mtllib", "s"):
            out.append(line)
    # drop runs of o/g/usemtl lines that no longer have faces
    return "".join(out).encode()


def obj_mesh(lines):
    """Positions and 0-based face index lists (relative indices resolved) of OBJ text lines."""
    verts, faces = [], []
    for line in lines:
        w = line.split()
        if w and w[0] == "v":
            verts.append(tuple(float(x) for x in w[1:4]))
        elif w and w[0] == "f":
            ids = [int(t.split("/")[0]) for t in w[1:]]
            faces.append([i - 1 if i > 0 else len(verts) + i for i in ids])
    return verts, faces


def ply(verts, faces, fmt):
    head = (f"ply\nformat {fmt} 1.0\ncomment converted from the Cornell box by fuzz/seeds/make_seeds.py\n"
            f"element vertex {len(verts)}\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\n"
            f"element face {len(faces)}\nproperty list uchar int vertex_indices\nelement extra 1\nproperty double w\nend_header\n").encode()
    if fmt == "ascii":
        body = "".join(f"{x} {y} {z} 200\n" for x, y, z in verts)
        body += "".join(f"{len(f)} {' '.join(map(str, f))}\n" for f in faces) + "1.5\n"
        return head + body.encode()
    e = "<" if fmt == "binary_little_endian" else ">"
    body = b"".join(struct.pack(e + "fffB", *v, 200) for v in verts)
    body += b"".join(struct.pack(e + "B" + "i" * len(f), len(f), *f) for f in faces) + struct.pack(e + "d", 1.5)
    return head + body


def tiny_png(size=8):
    img = Image.new("RGBA", (size, size))
    img.putdata([(90, 140, 60, 255 if (x + y) % 3 else 0) for y in range(size) for x in range(size)])
    buf = io.BytesIO()
    img.save(buf, "PNG")
    return buf.getvalue()


def glb(doc, bin_):
    js = json.dumps(doc, separators=(",", ":")).encode()
    js += b" " * (-len(js) % 4)
    bin_ += b"\0" * (-len(bin_) % 4)
    total = 12 + 8 + len(js) + 8 + len(bin_)
    return (b"glTF" + struct.pack("<II", 2, total) + struct.pack("<I", len(js)) + b"JSON" + js
            + struct.pack("<I", len(bin_)) + b"BIN\0" + bin_)


def main():
    # two small real PLY files shipped with ply-rs (the crate aokit reads PLY with)
    reg = os.path.expanduser("~/.cargo/registry/src")
    for d in sorted(os.listdir(reg)) if os.path.isdir(reg) else []:
        ex = os.path.join(reg, d, "ply-rs-0.1.3", "example_plys")
        for name in ("house_2_ok_little_endian.ply", "greg_turk_example1_ok_ascii.ply"):
            if os.path.exists(os.path.join(ex, name)):
                write("ply", name, open(os.path.join(ex, name), "rb").read())
    cornell = os.path.join(ROOT, "assets", "scenes", "cornell_box")
    obj = open(os.path.join(cornell, "cornell_box.obj"), "rb").read()
    mtl = open(os.path.join(cornell, "cornell_box.mtl"), "rb").read()
    write("obj", "cornell_box.obj", obj + SEP + mtl)
    write("obj", "cornell_box_no_mtl.obj", obj)
    write("obj", "quad_uv.obj", b"mtllib q.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
          b"vn 0 0 1\nusemtl m\nf 1/1/1 2/2/1 3/3/1 4/4/1\nf -4/-4 -3/-3 -2/-2\n" + SEP + b"newmtl m\nKd 1 1 1\n")
    sponza = os.path.join(SCENES, "bvh-0.13.0", "sponza.obj")
    kitchen = os.path.join(SCENES, "obvhs-0.4.0", "kitchen.obj")
    if os.path.exists(sponza):
        write("obj", "sponza_small.obj", small_obj(sponza, 300))
    if os.path.exists(kitchen):
        kmtl = open(os.path.join(SCENES, "obvhs-0.4.0", "kitchen.mtl"), "rb").read()[:1500]
        write("obj", "kitchen_small.obj", small_obj(kitchen, 150) + SEP + kmtl)

    verts, faces = obj_mesh(open(os.path.join(cornell, "cornell_box.obj")))
    for fmt, name in [("ascii", "cornell_ascii.ply"), ("binary_little_endian", "cornell_le.ply"),
                      ("binary_big_endian", "cornell_be.ply")]:
        data = ply(verts, faces, fmt)
        write("ply", name, data)
        write("ply_gz", name + ".gz", gzip.compress(data, mtime=0))
    if os.path.exists(sponza):
        sv, sf = obj_mesh(small_obj(sponza, 150).decode().splitlines())
        data = ply(sv, sf, "binary_little_endian")
        write("ply", "sponza_small_le.ply", data)
        write("ply_gz", "sponza_small_le.ply.gz", gzip.compress(data, mtime=0))

    # glTF: the Cornell box (indexed u16, interleaved positions with a stride, a sparse accessor)
    pos = b"".join(struct.pack("<fff", *v) + b"\0\0\0\0" for v in verts)  # stride 16
    tris = [t for f in faces for t in ([f[0], f[k - 1], f[k]] for k in range(2, len(f)))]
    idx = b"".join(struct.pack("<HHH", *t) for t in tris)
    idx += b"\0" * (-len(idx) % 4)
    sparse_i = struct.pack("<HH", 0, 1)
    sparse_v = struct.pack("<ffffff", 552.8, 1.0, 0.0, 0.0, 1.0, 0.0)
    bin_ = pos + idx + sparse_i + sparse_v
    o1 = len(pos); o2 = o1 + len(idx); o3 = o2 + len(sparse_i)
    lo = [min(v[k] for v in verts) for k in range(3)]; hi = [max(v[k] for v in verts) for k in range(3)]
    doc = {
        "asset": {"version": "2.0"}, "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"children": [1], "scale": [0.01, 0.01, 0.01]}, {"mesh": 0, "translation": [0, 0, 1]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}, {"attributes": {"POSITION": 2}, "mode": 4}]}],
        "buffers": [{"byteLength": len(bin_)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(pos), "byteStride": 16},
                        {"buffer": 0, "byteOffset": o1, "byteLength": len(idx)},
                        {"buffer": 0, "byteOffset": o2, "byteLength": len(sparse_i)},
                        {"buffer": 0, "byteOffset": o3, "byteLength": len(sparse_v)}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": len(verts), "type": "VEC3", "min": lo, "max": hi},
                      {"bufferView": 1, "componentType": 5123, "count": 3 * len(tris), "type": "SCALAR"},
                      {"componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [552.8, 1, 0],
                       "sparse": {"count": 2, "indices": {"bufferView": 2, "componentType": 5123},
                                  "values": {"bufferView": 3}}}],
    }
    write("gltf", "cornell.glb", glb(doc, bin_))
    doc_uri = json.loads(json.dumps(doc))
    doc_uri["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(bin_).decode()
    write("gltf", "cornell.gltf", json.dumps(doc_uri, indent=1).encode())

    oak_dir = [d for d in os.listdir(SCENES) if d.startswith("castle-game-engine-doc")] if os.path.isdir(SCENES) else []
    if oak_dir:
        d = os.path.join(SCENES, oak_dir[0])
        doc = json.load(open(os.path.join(d, "oaktree.gltf")))
        bin_ = open(os.path.join(d, "oaktree.bin"), "rb").read()
        doc.pop("animations", None)
        png = tiny_png()
        # GLB: the leaf texture from a buffer view, the bark texture left as an (unread) file URI
        g = json.loads(json.dumps(doc))
        g["buffers"] = [{"byteLength": len(bin_) + len(png)}]
        g["bufferViews"].append({"buffer": 0, "byteOffset": len(bin_), "byteLength": len(png)})
        g["images"][0] = {"mimeType": "image/png", "bufferView": len(g["bufferViews"]) - 1}
        write("gltf", "oaktree.glb", glb(g, bin_ + png))
        # .gltf: the buffer and the leaf texture as data URIs
        doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(bin_).decode()
        doc["images"][0] = {"uri": "data:image/png;base64," + base64.b64encode(png).decode()}
        write("gltf", "oaktree.gltf", json.dumps(doc, separators=(",", ":")).encode())


if __name__ == "__main__":
    main()
