#!/usr/bin/env python3
"""Writes the mesh files of the mesh-import tests (run once; the outputs are committed).

Good files hold the same cube, edge 0.2 m, centred at (0.1, 0.2, 0.3), in every tested format;
bad files hold one problem each.
"""
import base64
import json
import os
import struct

EDGE = 0.2
CENTRE = (0.1, 0.2, 0.3)
CORNERS = [(CENTRE[0] + sx * EDGE / 2, CENTRE[1] + sy * EDGE / 2, CENTRE[2] + sz * EDGE / 2)
           for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]
# Outward triangles of the cube with corner index 4 sx + 2 sy + sz (0 for -, 1 for +).
QUADS = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
TRIANGLES = [t for a, b, c, d in QUADS for t in ((a, b, c), (a, c, d))]


def fmt(v):
    return " ".join(repr(x) for x in v)


def write(name, text):
    with open(name, "w") as out:
        out.write(text)


def obj(name, points, triangles, header="cube"):
    lines = [f"# {header}"] + [f"v {fmt(p)}" for p in points]
    lines += [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in triangles]
    write(name, "\n".join(lines) + "\n")


def normal(a, b, c):
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    length = sum(x * x for x in n) ** 0.5
    return tuple(x / length for x in n)


def stl_ascii(name, points, triangles):
    lines = ["solid cube"]
    for t in triangles:
        a, b, c = (points[i] for i in t)
        lines += [f"  facet normal {fmt(normal(a, b, c))}", "    outer loop"]
        lines += [f"      vertex {fmt(p)}" for p in (a, b, c)]
        lines += ["    endloop", "  endfacet"]
    write(name, "\n".join(lines + ["endsolid cube"]) + "\n")


def stl_binary(name, points, triangles):
    data = b"binary cube".ljust(80, b" ") + struct.pack("<I", len(triangles))
    for t in triangles:
        a, b, c = (points[i] for i in t)
        data += struct.pack("<12fH", *normal(a, b, c), *a, *b, *c, 0)
    with open(name, "wb") as out:
        out.write(data)


def ply(name, points, triangles):
    lines = ["ply", "format ascii 1.0", f"element vertex {len(points)}", "property float x",
             "property float y", "property float z", f"element face {len(triangles)}",
             "property list uchar int vertex_indices", "end_header"]
    lines += [fmt(p) for p in points] + [f"3 {a} {b} {c}" for a, b, c in triangles]
    write(name, "\n".join(lines) + "\n")


def off(name, points, triangles):
    lines = ["OFF", f"{len(points)} {len(triangles)} 0"] + [fmt(p) for p in points]
    lines += [f"3 {a} {b} {c}" for a, b, c in triangles]
    write(name, "\n".join(lines) + "\n")


def gltf_document(points, triangles, node, uri):
    positions = b"".join(struct.pack("<3f", *p) for p in points)
    indices = b"".join(struct.pack("<3H", *t) for t in triangles)
    buffer = positions + indices
    document = {
        "asset": {"version": "2.0", "generator": "rockfall tests/data/meshes/make_meshes.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [node],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "buffers": [{"byteLength": len(buffer)}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": len(positions), "target": 34962},
            {"buffer": 0, "byteOffset": len(positions), "byteLength": len(indices),
             "target": 34963}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(points), "type": "VEC3",
             "min": [min(p[i] for p in points) for i in range(3)],
             "max": [max(p[i] for p in points) for i in range(3)]},
            {"bufferView": 1, "componentType": 5123, "count": 3 * len(triangles),
             "type": "SCALAR"}],
    }
    if uri:
        document["buffers"][0]["uri"] = ("data:application/octet-stream;base64," +
                                         base64.b64encode(buffer).decode())
    return document, buffer


def gltf(name, points, triangles, node):
    document, _ = gltf_document(points, triangles, node, True)
    write(name, json.dumps(document, indent=1) + "\n")


def glb(name, points, triangles):
    document, buffer = gltf_document(points, triangles, {"mesh": 0}, False)
    text = json.dumps(document).encode()
    text += b" " * (-len(text) % 4)
    buffer += b"\0" * (-len(buffer) % 4)
    chunks = (struct.pack("<I4s", len(text), b"JSON") + text +
              struct.pack("<I4s", len(buffer), b"BIN\0") + buffer)
    with open(name, "wb") as out:
        out.write(struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks)


os.chdir(os.path.dirname(os.path.abspath(__file__)))
obj("cube.obj", CORNERS, TRIANGLES)
stl_ascii("cube.stl", CORNERS, TRIANGLES)
stl_binary("cube_binary.stl", CORNERS, TRIANGLES)
ply("cube.ply", CORNERS, TRIANGLES)
off("cube.off", CORNERS, TRIANGLES)
gltf("cube.gltf", CORNERS, TRIANGLES, {"mesh": 0})
glb("cube.glb", CORNERS, TRIANGLES)
# The node doubles the cube and moves it: the hull must apply node transforms.
gltf("cube_scaled_node.gltf", CORNERS, TRIANGLES,
     {"mesh": 0, "scale": [2.0, 2.0, 2.0], "translation": [1.0, 0.0, 0.0]})
# A bare point cloud: vertices without faces.
write("cube_points.obj", "# cube corners only\n" + "".join(f"v {fmt(p)}\n" for p in CORNERS))

# One problem each.
write("empty.obj", "# an OBJ file with comments only and no vertex at all, long enough that\n"
                   "# the reader does not reject it as too small before looking inside\n")
write("empty.stl", "solid empty\nendsolid empty\n")
nan = [list(p) for p in CORNERS]
nan[5][1] = float("nan")
write("nan.obj", "".join(f"v {p[0]!r} {'nan' if p[1] != p[1] else repr(p[1])} {p[2]!r}\n"
                         for p in nan) + "".join(f"f {a + 1} {b + 1} {c + 1}\n"
                                                  for a, b, c in TRIANGLES))
write("inf.off", "OFF\n8 12 0\n" + "".join(
    f"{fmt(p)}\n" if i != 2 else f"{p[0]!r} {p[1]!r} inf\n" for i, p in enumerate(CORNERS)) +
    "".join(f"3 {a} {b} {c}\n" for a, b, c in TRIANGLES))
square = [(0.0, 0.0, 0.0), (0.2, 0.0, 0.0), (0.2, 0.2, 0.0), (0.0, 0.2, 0.0), (0.1, 0.1, 0.0)]
obj("flat.obj", square, [(0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)], "coplanar points")
line = [(0.1 * i, 0.05 * i, 0.02 * i) for i in range(6)]
ply("collinear.ply", line, [(0, 1, 2), (2, 3, 4), (3, 4, 5)])
obj("km_rock.obj", [tuple(1000.0 * (x - c) / EDGE for x, c in zip(p, CENTRE)) for p in CORNERS],
    TRIANGLES, "a 1000 m cube")
stl_ascii("micron_rock.stl",
          [tuple(1e-6 * (x - c) / EDGE for x, c in zip(p, CENTRE)) for p in CORNERS], TRIANGLES)
obj("far_away.obj", [(x + 1e6, y, z) for x, y, z in CORNERS], TRIANGLES,
    "a 0.2 m cube a thousand kilometres from the origin")
# Found by fuzz/fuzz_mesh_off: an OFF file that declares more faces than it lists gets faces
# without corners from assimp, whose triangulation then aborts on an assertion.
write("short_faces.off", "OFF\n8 12 0\n" + "".join(f"{fmt(p)}\n" for p in CORNERS) +
      "".join(f"3 {a} {b} {c}\n" for a, b, c in TRIANGLES[:10]))
# A PLY face naming a vertex past the end, which assimp passes on as it is.
ply("bad_index.ply", CORNERS, TRIANGLES[:11] + [(0, 1, 8)])
write("garbage.stl", "this is not an STL file, neither ASCII nor binary\n" * 3)
write("garbage.ply", "not a ply header\n1 2 3\n")
write("unknown.xyz", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n")
write("no_extension", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n")
os.makedirs("folder.obj", exist_ok=True)
write("folder.obj/README", "A folder named like a mesh file: reading it must fail cleanly.\n")
