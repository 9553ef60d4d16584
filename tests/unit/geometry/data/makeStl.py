#!/usr/bin/env python3
"""Writes the STL surfaces the geometry tests read, as ASCII STL with outward normals:

cube.stl    the unit cube [0, 1]^3, 12 triangles, volume 1;
sphere.stl  an icosphere of radius 1 about the origin: the icosahedron with each face subdivided
            `levels` times and every vertex pushed out onto the sphere, so all vertices lie on it
            and the polyhedron is inscribed (its volume is below 4/3 pi, printed below).

Run from this folder: python3 makeStl.py
"""
import math


def write(name, triangles):
    with open(name, "w") as f:
        f.write(f"solid {name[:-4]}\n")
        for a, b, c in triangles:
            u = [b[i] - a[i] for i in range(3)]
            v = [c[i] - a[i] for i in range(3)]
            n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
            length = math.sqrt(sum(x * x for x in n))
            f.write("  facet normal %.9g %.9g %.9g\n    outer loop\n" % tuple(x / length for x in n))
            for p in (a, b, c):
                f.write("      vertex %.12g %.12g %.12g\n" % tuple(p))
            f.write("    endloop\n  endfacet\n")
        f.write(f"endsolid {name[:-4]}\n")


def volume(triangles):
    # Divergence theorem: the sum of the signed tetrahedra (origin, a, b, c).
    return sum(
        (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6
        for a, b, c in triangles)


def cube():
    corners = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
    index = lambda x, y, z: 4 * x + 2 * y + z
    quads = [  # each face counter-clockwise seen from outside
        (index(0, 0, 0), index(0, 0, 1), index(0, 1, 1), index(0, 1, 0)),  # x = 0
        (index(1, 0, 0), index(1, 1, 0), index(1, 1, 1), index(1, 0, 1)),  # x = 1
        (index(0, 0, 0), index(1, 0, 0), index(1, 0, 1), index(0, 0, 1)),  # y = 0
        (index(0, 1, 0), index(0, 1, 1), index(1, 1, 1), index(1, 1, 0)),  # y = 1
        (index(0, 0, 0), index(0, 1, 0), index(1, 1, 0), index(1, 0, 0)),  # z = 0
        (index(0, 0, 1), index(1, 0, 1), index(1, 1, 1), index(0, 1, 1)),  # z = 1
    ]
    tris = []
    for a, b, c, d in quads:
        tris += [(corners[a], corners[b], corners[c]), (corners[a], corners[c], corners[d])]
    return tris


def icosphere(levels):
    t = (1 + math.sqrt(5)) / 2
    vertices = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
                (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
             (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    unit = lambda p: tuple(x / math.sqrt(sum(y * y for y in p)) for x in p)
    tris = [tuple(unit(vertices[i]) for i in f) for f in faces]
    for _ in range(levels):
        finer = []
        for a, b, c in tris:
            ab, bc, ca = (unit(tuple((p[i] + q[i]) / 2 for i in range(3))) for p, q in ((a, b), (b, c), (c, a)))
            finer += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        tris = finer
    return tris


if __name__ == "__main__":
    write("cube.stl", cube())
    sphere = icosphere(3)
    write("sphere.stl", sphere)
    print("cube volume", volume(cube()))
    print("sphere: %d triangles, polyhedron volume %.9f, 4/3 pi = %.9f, ratio %.6f"
          % (len(sphere), volume(sphere), 4 * math.pi / 3, volume(sphere) / (4 * math.pi / 3)))
