#!/usr/bin/env python3
"""Writes the mesh files that examples/mesh_files.rt reads (trace's mesh_file extension):

  examples/meshes/knot.obj     a trefoil-knot tube with vertex normals (OBJ, `f v//vn`)
  examples/meshes/terrain.ply  a height-field patch, binary little-endian PLY, no normals

Deterministic: rerunning gives byte-identical files. Usage: scripts/make_meshes.py
"""
import math
import os
import struct

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "examples", "meshes")


def knot_tube(segments, sides, radius):
    """A trefoil-knot tube: vertices, unit normals, and quads (vertex indices, 0-based).
    Also used by scripts/speed.py for its instanced mesh."""
    def centre(t):
        return (math.sin(t) + 2 * math.sin(2 * t), math.cos(t) - 2 * math.cos(2 * t), -math.sin(3 * t))

    verts, norms, faces = [], [], []
    for i in range(segments):
        t = 2 * math.pi * i / segments
        c = centre(t)
        d = [b - a for a, b in zip(centre(t - 1e-4), centre(t + 1e-4))]
        dl = math.sqrt(sum(x * x for x in d))
        d = [x / dl for x in d]
        # A frame around the tangent: any vector not parallel to it, made orthogonal.
        up = (0.0, 0.0, 1.0) if abs(d[2]) < 0.9 else (1.0, 0.0, 0.0)
        u = [up[1] * d[2] - up[2] * d[1], up[2] * d[0] - up[0] * d[2], up[0] * d[1] - up[1] * d[0]]
        ul = math.sqrt(sum(x * x for x in u))
        u = [x / ul for x in u]
        w = [d[1] * u[2] - d[2] * u[1], d[2] * u[0] - d[0] * u[2], d[0] * u[1] - d[1] * u[0]]
        for j in range(sides):
            a = 2 * math.pi * j / sides
            n = [math.cos(a) * u[k] + math.sin(a) * w[k] for k in range(3)]
            verts.append([c[k] + radius * n[k] for k in range(3)])
            norms.append(n)
    for i in range(segments):
        for j in range(sides):
            a = i * sides + j
            b = i * sides + (j + 1) % sides
            c = ((i + 1) % segments) * sides + j
            d = ((i + 1) % segments) * sides + (j + 1) % sides
            faces.append((a, c, d, b))
    return verts, norms, faces


def knot(segments=160, sides=12, radius=0.35):
    verts, norms, faces = knot_tube(segments, sides, radius)  # quads, split into fans by the reader
    lines = ["# trefoil knot tube, written by scripts/make_meshes.py", "o knot"]
    lines += ["v %.6f %.6f %.6f" % tuple(v) for v in verts]
    lines += ["vn %.6f %.6f %.6f" % tuple(n) for n in norms]
    lines += ["f " + " ".join("%d//%d" % (k + 1, k + 1) for k in f) for f in faces]
    with open(os.path.join(OUT, "knot.obj"), "w") as fh:
        fh.write("\n".join(lines) + "\n")


def terrain(n=64, size=8.0):
    def height(x, z):
        return 0.35 * math.sin(1.3 * x) * math.cos(0.9 * z) + 0.15 * math.sin(3.1 * x + 2.3 * z)

    verts = []
    for j in range(n):
        for i in range(n):
            x = size * (i / (n - 1) - 0.5)
            z = size * (j / (n - 1) - 0.5)
            verts.append((x, height(x, z), z))
    faces = []
    for j in range(n - 1):
        for i in range(n - 1):
            a = j * n + i
            faces.append((a, a + n, a + 1))
            faces.append((a + 1, a + n, a + n + 1))
    header = (
        "ply\nformat binary_little_endian 1.0\ncomment written by scripts/make_meshes.py\n"
        "element vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
        "element face %d\nproperty list uchar int vertex_indices\nend_header\n" % (len(verts), len(faces))
    )
    with open(os.path.join(OUT, "terrain.ply"), "wb") as fh:
        fh.write(header.encode())
        for v in verts:
            fh.write(struct.pack("<3f", *v))
        for f in faces:
            fh.write(struct.pack("<B3i", 3, *f))


if __name__ == "__main__":
    os.makedirs(OUT, exist_ok=True)
    knot()
    terrain()
