#!/usr/bin/env python3
"""Writes the mesh stages' files (levels/*/) and the mesh test files (tests/data/meshes/).

Run from the repository root: python3 tools/make_meshes.py. The files are committed; this
script is how they were made. y is up, the camera looks from +z (docs/level-format.md)."""
import itertools, json, base64, math, struct

PHI = (1 + 5 ** 0.5) / 2


def hull_faces(points, eps=1e-9):
    """Faces of the convex hull of points (all on the hull), counter-clockwise from outside."""
    faces, seen = [], set()
    n = len(points)
    sub = lambda a, b: [a[i] - b[i] for i in range(3)]
    cross = lambda a, b: [a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0]]
    dot = lambda a, b: sum(a[i]*b[i] for i in range(3))
    for i, j, k in itertools.combinations(range(n), 3):
        nrm = cross(sub(points[j], points[i]), sub(points[k], points[i]))
        ln = dot(nrm, nrm) ** 0.5
        if ln < eps: continue
        nrm = [c / ln for c in nrm]
        s = [dot(nrm, sub(p, points[i])) for p in points]
        if min(s) < -eps and max(s) > eps: continue
        if max(s) > eps: nrm = [-c for c in nrm]
        on = tuple(m for m in range(n) if abs(s[m]) <= eps)
        if on in seen: continue
        seen.add(on)
        c = [sum(points[m][a] for m in on) / len(on) for a in range(3)]
        u = sub(points[on[0]], c); lu = dot(u, u) ** 0.5; u = [x / lu for x in u]
        w = cross(nrm, u)
        faces.append(sorted(on, key=lambda m: math.atan2(dot(w, sub(points[m], c)), dot(u, sub(points[m], c)))))
    return faces


def write_obj(path, points, faces, comment):
    with open(path, "w") as f:
        f.write(f"# {comment}\n")
        for p in points: f.write("v %.9f %.9f %.9f\n" % tuple(p))
        for face in faces: f.write("f " + " ".join(str(i + 1) for i in face) + "\n")


def write_ply(path, points, faces, comment):
    with open(path, "w") as f:
        f.write(f"ply\nformat ascii 1.0\ncomment {comment}\nelement vertex {len(points)}\n"
                "property float x\nproperty float y\nproperty float z\n"
                f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n")
        for p in points: f.write("%.9f %.9f %.9f\n" % tuple(p))
        for face in faces: f.write(f"{len(face)} " + " ".join(map(str, face)) + "\n")


def triangles(faces):
    return [[face[0], face[k], face[k + 1]] for face in faces for k in range(1, len(face) - 1)]


def write_stl(path, points, faces):
    with open(path, "w") as f:
        f.write("solid mesh\n")
        for t in triangles(faces):
            f.write("  facet normal 0 0 0\n    outer loop\n")
            for i in t: f.write("      vertex %.9f %.9f %.9f\n" % tuple(points[i]))
            f.write("    endloop\n  endfacet\n")
        f.write("endsolid mesh\n")


def write_gltf(path, points, faces):
    tris = triangles(faces)
    pos = b"".join(struct.pack("<3f", *p) for p in points)
    idx = b"".join(struct.pack("<3I", *t) for t in tris)
    buf = pos + idx
    lo = [min(p[a] for p in points) for a in range(3)]
    hi = [max(p[a] for p in points) for a in range(3)]
    doc = {
        "asset": {"version": "2.0"},
        "scenes": [{"nodes": [0]}], "scene": 0, "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "buffers": [{"byteLength": len(buf), "uri": "data:application/octet-stream;base64," + base64.b64encode(buf).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(pos)},
                        {"buffer": 0, "byteOffset": len(pos), "byteLength": len(idx)}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": len(points), "type": "VEC3", "min": lo, "max": hi},
                      {"bufferView": 1, "componentType": 5125, "count": 3 * len(tris), "type": "SCALAR"}],
    }
    with open(path, "w") as f: json.dump(doc, f, indent=1)


# A triangular prism: equilateral ends (side 2) facing the camera and away, 3 long, lying on a side.
h = 3 ** 0.5
prism = [[-1.5, 0, 1], [-1.5, 0, -1], [-1.5, h, 0], [1.5, 0, 1], [1.5, 0, -1], [1.5, h, 0]]
# Turned so that the triangles look along x: the ends are left and right; the camera sees a side.
prism_faces = hull_faces(prism)
# The level's mesh is PLY: assimp 5.2's OBJ reader zero-fills a 4 MB buffer on every read (about
# 1 ms, and about 8 ms the first time in a process), PLY reads in about 0.1 ms.
write_ply("levels/prism/prism.ply", prism, prism_faces, "a triangular prism: ends of side 2, 3 long (tools/make_meshes.py)")
write_obj("tests/data/meshes/prism.obj", prism, prism_faces, "a triangular prism: ends of side 2, 3 long (tools/make_meshes.py)")
write_stl("tests/data/meshes/prism.stl", prism, prism_faces)
write_ply("tests/data/meshes/prism.ply", prism, prism_faces, "prism")
write_gltf("tests/data/meshes/prism.gltf", prism, prism_faces)

# A truncated icosahedron (a football): 12 pentagons and 20 hexagons, edge 2.
def even_permutations(v):
    x, y, z = v
    return [(x, y, z), (y, z, x), (z, x, y)]
ti = set()
for base in [(0, 1, 3 * PHI), (1, 2 + PHI, 2 * PHI), (PHI, 2, 2 * PHI + 1)]:
    for sx, sy, sz in itertools.product([1, -1], repeat=3):
        for p in even_permutations((sx * base[0], sy * base[1], sz * base[2])):
            ti.add(tuple(round(c, 12) + 0.0 for c in p))
ti = sorted(ti)
assert len(ti) == 60, len(ti)
ti_faces = hull_faces([list(p) for p in ti])
assert len(ti_faces) == 32, len(ti_faces)
write_ply("levels/soccer_ball/truncated_icosahedron.ply", [list(p) for p in ti], ti_faces,
          "a truncated icosahedron: 12 pentagons, 20 hexagons, edge 2 (tools/make_meshes.py)")

# Broken meshes for the error tests.
cube = [[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)]
cube_faces = hull_faces(cube)
write_obj("tests/data/meshes/open_box.obj", cube, cube_faces[:-1], "a cube with a face missing")
l_shape = [[0, 0, 0], [2, 0, 0], [2, 1, 0], [1, 1, 0], [1, 2, 0], [0, 2, 0]]
l_faces = [[0, 1, 2, 3, 4, 5]]
l_points = l_shape + [[x, y, 1] for x, y, _ in l_shape]
sides = [[i, (i + 1) % 6 + 6, i + 6][::-1] for i in range(6)]
quads = [[i, (i + 1) % 6, (i + 1) % 6 + 6, i + 6] for i in range(6)]
write_obj("tests/data/meshes/l_prism.obj", l_points,
          [[5, 4, 3, 2, 1, 0], [6, 7, 8, 9, 10, 11]] + quads, "an L-shaped prism: not convex")
with open("tests/data/meshes/not_a_mesh.obj", "w") as f: f.write("this is not a mesh file\n")
print("written")
