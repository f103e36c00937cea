"""The paper-scale scene of Benchmarks/VTK/BenchmarkFilterEdits.cxx (PaperScale()) in Python:
circles in clusters of overlapping ones on a surface, each circle's control points given as
exact surface points (triangle and barycentric weights of the closest surface point), two
versions of every circle (the second moved by 5 % of its radius and rotated by half a
control-point step). The same generator (std::mt19937, std::uniform_real_distribution's
libstdc++ draw), the same arithmetic in the same order and the same closest-point locator
(vtkStaticCellLocator) as the C++ benchmark, so both measure the same circles.

Used by paper_scale_update.py; runs in pvpython or /usr/bin/python3 (python3-paraview's VTK).
"""
import json
import math
import os

from vtkmodules.vtkCommonCore import reference, vtkIdList
from vtkmodules.vtkCommonDataModel import vtkGenericCell, vtkStaticCellLocator

VERSIONS = 2


class MT19937:
    """std::mt19937 (32-bit Mersenne twister, init_genrand seeding)."""

    def __init__(self, seed):
        self.mt = [0] * 624
        self.mt[0] = seed & 0xFFFFFFFF
        for i in range(1, 624):
            prev = self.mt[i - 1]
            self.mt[i] = (1812433253 * (prev ^ (prev >> 30)) + i) & 0xFFFFFFFF
        self.index = 624

    def __call__(self):
        if self.index >= 624:
            mt = self.mt
            for i in range(624):
                y = (mt[i] & 0x80000000) | (mt[(i + 1) % 624] & 0x7FFFFFFF)
                mt[i] = mt[(i + 397) % 624] ^ (y >> 1) ^ (0x9908B0DF if y & 1 else 0)
            self.index = 0
        y = self.mt[self.index]
        self.index += 1
        y ^= y >> 11
        y ^= (y << 7) & 0x9D2C5680
        y ^= (y << 15) & 0xEFC60000
        y ^= y >> 18
        return y

    def unit(self):
        """std::uniform_real_distribution<double>(0, 1) in libstdc++: generate_canonical with
        two 32-bit draws, the first the low part."""
        low = float(self())
        high = float(self())
        value = (low + high * 4294967296.0) / 18446744073709551616.0
        return value if value < 1.0 else math.nextafter(1.0, 0.0)


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def scale(a, s):
    return (s * a[0], s * a[1], s * a[2])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def norm(a):
    return math.sqrt(dot(a, a))


def normalized(a):
    n = norm(a)
    return scale(a, 1.0 / n) if n > 0 else a


class Surface:
    """A triangle mesh with the closest-point locator the placement uses."""

    def __init__(self, mesh):
        self.mesh = mesh
        self.locator = vtkStaticCellLocator()
        self.locator.SetDataSet(mesh)
        self.locator.BuildLocator()
        b = mesh.GetBounds()
        self.diagonal = norm((b[1] - b[0], b[3] - b[2], b[5] - b[4]))
        self.cell = vtkGenericCell()
        self.ids = vtkIdList()

    def point(self, i):
        return tuple(self.mesh.GetPoint(i))

    def triangle(self, t):
        self.mesh.GetCellPoints(t, self.ids)
        return (self.ids.GetId(0), self.ids.GetId(1), self.ids.GetId(2))

    def area_normal(self, t):
        ids = self.triangle(t)
        a = self.point(ids[0])
        return cross(sub(self.point(ids[1]), a), sub(self.point(ids[2]), a))

    def snap(self, x):
        """(triangle, u, v, position, unit normal) of the closest surface point of x."""
        closest = [0.0, 0.0, 0.0]
        triangle, sub_id, dist2 = reference(0), reference(0), reference(0.0)
        self.locator.FindClosestPoint(list(x), closest, self.cell, triangle, sub_id, dist2)
        t = int(triangle)
        if t < 0:
            return None
        ids = self.triangle(t)
        a = self.point(ids[0])
        e1, e2 = sub(self.point(ids[1]), a), sub(self.point(ids[2]), a)
        d = sub(tuple(closest), a)
        d11, d12, d22 = dot(e1, e1), dot(e1, e2), dot(e2, e2)
        d1, d2 = dot(d, e1), dot(d, e2)
        det = d11 * d22 - d12 * d12
        if det <= 0:
            return None
        u = max(0.0, (d22 * d1 - d12 * d2) / det)
        v = max(0.0, (d11 * d2 - d12 * d1) / det)
        if u + v > 1:
            u /= u + v
            v = 1 - u
        position = add(a, add(scale(e1, u), scale(e2, v)))
        return (t, u, v, position, normalized(cross(e1, e2)))


class Circle:
    def __init__(self, center, u, v, n, radius):
        self.center, self.u, self.v, self.n, self.radius = center, u, v, n, radius


def make_circle(s, x, radius):
    snapped = s.snap(x)
    if snapped is None:
        return None
    seed_normal = snapped[4]
    h = 0.5 * radius
    p = snapped[3]
    cells = vtkIdList()
    s.locator.FindCellsWithinBounds([p[0] - h, p[0] + h, p[1] - h, p[1] + h, p[2] - h,
                                     p[2] + h], cells)
    total = (0.0, 0.0, 0.0)
    for k in range(cells.GetNumberOfIds()):
        n = s.area_normal(cells.GetId(k))
        if dot(n, seed_normal) > 0:
            total = add(total, n)
    n = normalized(total) if norm(total) > 0 else seed_normal
    a = [abs(n[0]), abs(n[1]), abs(n[2])]
    least = (0 if a[0] < a[2] else 2) if a[0] < a[1] else (1 if a[1] < a[2] else 2)
    axis = [0.0, 0.0, 0.0]
    axis[least] = 1.0
    u = normalized(cross(n, tuple(axis)))
    return Circle(p, u, cross(n, u), n, radius)


def circle_points(s, c, count, phase, offset):
    """The control points of one version of a circle, or None where the surface is not close
    to a disc (as the C++ CirclePoints)."""
    points = []
    center = add(c.center, scale(c.u, offset * c.radius))
    chord = 2 * c.radius * math.sin(math.pi / count)
    for i in range(count):
        angle = phase + 2 * math.pi * i / count
        x = add(center, add(scale(c.u, c.radius * math.cos(angle)),
                            scale(c.v, c.radius * math.sin(angle))))
        cp = s.snap(x)
        if (cp is None or norm(sub(cp[3], x)) > 0.25 * c.radius or dot(cp[4], c.n) < 0.3 or
                (points and norm(sub(cp[3], points[-1][3])) < 0.3 * chord)):
            return None
        points.append(cp)
    if norm(sub(points[0][3], points[-1][3])) < 0.3 * chord:
        return None
    return points


def version_points(s, c, count, version):
    return circle_points(s, c, count, version * math.pi / count, 0.05 * version)


def place_circles(s, number, radius, cluster_size, control_points, seed):
    rng = MT19937(seed)
    circles = []
    cluster_begin = 0
    n_points = s.mesh.GetNumberOfPoints()
    attempts = 0
    while len(circles) < number and attempts < 100000:
        attempts += 1
        seed_circle = len(circles) % cluster_size == 0
        if seed_circle:
            x = s.point(rng() % n_points)
        else:
            origin = circles[cluster_begin + rng() % (len(circles) - cluster_begin)]
            angle = 2 * math.pi * rng.unit()
            distance = radius * (1.1 + 0.4 * rng.unit())
            x = add(origin.center, add(scale(origin.u, distance * math.cos(angle)),
                                       scale(origin.v, distance * math.sin(angle))))
        c = make_circle(s, x, radius)
        if c is None:
            continue
        minimum = 4 * radius if seed_circle else 0.9 * radius
        if any(norm(sub(o.center, c.center)) < minimum for o in circles):
            continue
        if any(version_points(s, c, control_points, k) is None for k in range(VERSIONS)):
            continue
        if seed_circle:
            cluster_begin = len(circles)
        circles.append(c)
    return circles


SCENES = {
    # name: (circles, radius as a fraction of the diagonal, cluster size, control points, seed)
    "paper": (112, 0.027, 4, 32, 11),
    "ten": (10, 0.03, 5, 12, 7),
}


def scene_versions(mesh, name="paper", cache=None):
    """The scene's curves, one entry per version: (points as x y z..., triangle ids,
    barycentrics as u v..., curve sizes). `cache`: a JSON file holding them from an earlier
    run on the same mesh (placing 112 circles in Python takes tens of seconds), written when
    absent."""
    if cache and os.path.exists(cache):
        with open(cache) as f:
            stored = json.load(f)
        if stored.get("scene") == name and stored.get("cells") == mesh.GetNumberOfCells():
            return [tuple(v) for v in stored["versions"]]
    number, fraction, cluster, count, seed = SCENES[name]
    s = Surface(mesh)
    circles = place_circles(s, number, fraction * s.diagonal, cluster, count, seed)
    if len(circles) < number:
        raise RuntimeError("placed only %d of %d circles" % (len(circles), number))
    versions = []
    for v in range(VERSIONS):
        points, triangles, weights = [], [], []
        for c in circles:
            for t, u, w, p, _ in version_points(s, c, count, v):
                points += list(p)
                triangles.append(t)
                weights += [u, w]
        versions.append((points, triangles, weights, [count] * len(circles)))
    if cache:
        with open(cache, "w") as f:
            json.dump({"scene": name, "cells": mesh.GetNumberOfCells(), "versions": versions}, f)
    return versions
