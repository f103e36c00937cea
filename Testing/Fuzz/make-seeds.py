#!/usr/bin/env python3
"""Writes the seed corpora of the fuzz targets (Corpus/<Target>/): small valid and near-valid
inputs. Run from any folder; files found by fuzzing (crash-*, regressions) are kept beside them."""
import json
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))


def write(target, name, data):
    folder = os.path.join(HERE, "Corpus", target)
    os.makedirs(folder, exist_ok=True)
    if isinstance(data, str):
        data = data.encode()
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data)


# --- PLY files: a 2 x 2 square (ascii), a tetrahedron in both binary byte orders, quads and
# extra properties, and near-valid ones (truncated, bad counts, index out of range).
SQUARE_ASCII = ("ply\nformat ascii 1.0\ncomment 2 x 2 square\nelement vertex 9\n"
                "property float x\nproperty float y\nproperty float z\nelement face 8\n"
                "property list uchar int vertex_indices\nend_header\n"
                "0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0\n2 1 0\n0 2 0\n1 2 0\n2 2 0\n"
                "3 0 1 4\n3 0 4 3\n3 1 2 5\n3 1 5 4\n3 3 4 7\n3 3 7 6\n3 4 5 8\n3 4 8 7\n")
TETRA_V = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TETRA_F = [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)]


def binary_ply(order, vertex_type="float", fmt="f", count_type="uchar", count_fmt="B",
               index_type="int", index_fmt="i", extra=False):
    endian = "binary_little_endian" if order == "<" else "binary_big_endian"
    header = f"ply\nformat {endian} 1.0\nelement vertex {len(TETRA_V)}\n"
    header += "".join(f"property {vertex_type} {c}\n" for c in "xyz")
    if extra:
        header += "property uchar red\n"
    header += f"element face {len(TETRA_F)}\n"
    header += f"property list {count_type} {index_type} vertex_indices\nend_header\n"
    body = b""
    for v in TETRA_V:
        body += struct.pack(order + fmt * 3, *v) + (b"\x7f" if extra else b"")
    for f in TETRA_F:
        body += struct.pack(order + count_fmt + index_fmt * 3, 3, *f)
    return header.encode() + body


write("FuzzPlyReader", "square-ascii.ply", SQUARE_ASCII)
write("FuzzPlyReader", "tetra-le.ply", binary_ply("<"))
write("FuzzPlyReader", "tetra-be-double.ply", binary_ply(">", "double", "d"))
write("FuzzPlyReader", "tetra-le-uint-extra.ply",
      binary_ply("<", count_type="uint8", count_fmt="B", index_type="uint", index_fmt="I",
                 extra=True))
write("FuzzPlyReader", "quads-ascii.ply",
      "ply\nformat ascii 1.0\nelement vertex 6\nproperty double x\nproperty double y\n"
      "property double z\nproperty float nx\nelement face 2\n"
      "property list uchar uint vertex_indices\nproperty uchar red\nend_header\n"
      "0 0 0 1\n1 0 0 1\n2 0 0 1\n0 1 0 1\n1 1 0 1\n2 1 0 1\n4 0 1 4 3 5\n4 1 2 5 4 7\n")
write("FuzzPlyReader", "truncated-le.ply", binary_ply("<")[:-7])
write("FuzzPlyReader", "bad-index-ascii.ply", SQUARE_ASCII.replace("3 4 8 7\n", "3 4 8 90\n"))
write("FuzzPlyReader", "huge-count.ply",
      SQUARE_ASCII.replace("element face 8", "element face 4000000000"))

# --- Boolean expressions: mode byte (0 count, 1 ids, 2 any id; bit 7: large ids), shape count,
# 4 bytes per id, operation shapes a and b (0 = all), then the text.
def expression(mode, ids, a, b, text):
    data = bytes([mode, len(ids)]) + b"".join(struct.pack("<I", i) for i in ids)
    return data + bytes([a, b]) + text.encode()


write("FuzzBooleanExpression", "count-and.txt", expression(0, [0, 1, 2], 1, 2, "S0 & S1"))
write("FuzzBooleanExpression", "count-all.txt",
      expression(0, [0, 1, 2, 3], 0, 2, "(S0 & S1) ^ ~S2 | S3 - S1"))
write("FuzzBooleanExpression", "ids.txt",
      expression(0x81, [7, 1000000, 2147483647], 2, 3, "S7 | ~(S1000000 ^ S2147483647)"))
write("FuzzBooleanExpression", "any.txt", expression(2, [], 0, 0, "~~S12 - (S3&S4)"))
write("FuzzBooleanExpression", "unbalanced.txt", expression(0, [0, 1], 1, 1, "((S0 | S1)"))
write("FuzzBooleanExpression", "trailing.txt", expression(0, [0, 1], 1, 1, "S0 &"))
write("FuzzBooleanExpression", "overflow.txt", expression(2, [], 1, 1, "S99999999999 | S1"))
write("FuzzBooleanExpression", "utf8.txt", expression(1, [3], 1, 1, "S3 \u2227 S3 \xff"))
# Parentheses nested past the parser's limit (256): refused by name, not by a stack overflow.
write("FuzzBooleanExpression", "deep-parentheses.txt",
      expression(0, [0, 1], 1, 1, "(" * 1000 + "S0 | S1" + ")" * 1000))

# --- Core pipeline: surface kind and size, curves (count; per curve flags, point count, then per
# point triangle, u byte, v byte), tracer resolution, flood fill, operation, shapes a and b.
# Weight bytes below 64 pick special values (0: 0, 1: 1, 2: 1/2, 3: 1/3, 4: 1e-15, ...);
# 64 + k gives k/191.
def weight(x):
    return 64 + round(x * 191)


def pipeline(kind, size, curves, resolution=2, flood=0, op=0, a=0, b=1, extra=b""):
    data = bytes([kind, size]) + extra + bytes([len(curves) - 1])
    for flags, points in curves:
        data += bytes([flags, len(points) - 1])
        for t, u, v in points:
            data += bytes([t, u, v])
    return data + bytes([resolution, flood, op, a, b])


W = weight
tri = [(0, W(0.2), W(0.2)), (1, W(0.3), W(0.3)), (5, W(0.2), W(0.5))]
write("FuzzCorePipeline", "square-two-triangles.bin",
      pipeline(0, 3, [(0, tri), (8, [(2, W(0.1), W(0.1)), (6, W(0.4), W(0.1)), (7, W(0.3), W(0.5))])]))
write("FuzzCorePipeline", "square-vertices.bin",  # control points on vertices and edges
      pipeline(0, 2, [(0, [(0, 0, 0), (3, 1, 0), (6, 0, 1)]), (8, [(1, 2, 2), (4, 2, 0), (7, 0, 2)])],
               op=3))
write("FuzzCorePipeline", "jittered-bezier.bin",
      pipeline(1, 3, [(1, [(0, W(0.3), W(0.3)), (4, W(0.3), W(0.3)), (9, W(0.3), W(0.3)),
                           (12, W(0.2), W(0.2)), (16, W(0.2), W(0.2)), (3, W(0.1), W(0.6))])],
               extra=bytes([7]), op=1))
write("FuzzCorePipeline", "sphere.bin",
      pipeline(2, 1, [(0, [(0, W(0.3), W(0.3)), (20, W(0.3), W(0.3)), (40, W(0.3), W(0.3))]),
                      (8, [(10, W(0.3), W(0.3)), (30, W(0.3), W(0.3)), (60, W(0.3), W(0.3))])], op=2))
write("FuzzCorePipeline", "torus-open.bin",
      pipeline(3, 0x21, [(2, [(0, W(0.3), W(0.3)), (11, W(0.3), W(0.3)), (20, W(0.3), W(0.3))])]))
write("FuzzCorePipeline", "cylinder-big-shape.bin",
      pipeline(4, 0x13, [(4, [(0, W(0.3), W(0.3)), (9, W(0.3), W(0.3)), (17, W(0.3), W(0.3))]),
                         (0, [(2, W(0.5), W(0.2)), (5, W(0.3), W(0.3)), (12, W(0.3), W(0.3))])],
               a=255, b=255))
write("FuzzCorePipeline", "decoded-mesh.bin",
      pipeline(5, 0x0b, [(0, [(0, W(0.2), W(0.2)), (1, W(0.3), W(0.3)), (0, W(0.6), W(0.1))])],
               extra=bytes([0, 0, 0, 4, 0, 0, 4, 4, 0, 0, 4, 0]) + bytes([0, 1, 2, 0, 2, 3])))
write("FuzzCorePipeline", "one-point.bin", pipeline(0, 1, [(0, [(0, W(0.2), W(0.2))])]))

# --- Scenes: JSON, optionally followed by "\n#mesh\n" and the mesh file. Without a mesh part
# the target writes a 2 x 2 square (8 triangles) as mesh.ply and mesh.obj.
def scene(**keys):
    return json.dumps(dict({"model": "./data/models/mesh.ply"}, **keys))


points = [{"face": 0, "uv": [0.25, 0.25]}, {"face": 3, "uv": [0.5, 0.25]},
          {"face": 6, "uv": [0.2, 0.3]}, {"face": 7, "uv": [0.1, 0.1]},
          {"face": 2, "uv": [0.0, 1.0]}]
write("FuzzSceneReader", "valid.json",
      scene(points=points, polygons=[[], [0, 1, 2], [2, 3, 4], [], [1, 4]],
            are_closed=[True, True, False, True, True], shapes=[[0], [1, 2]],
            operations=[{"a": 1, "b": 3, "type": 2}]))
write("FuzzSceneReader", "default-shapes.json",
      scene(points=points[:4], polygons=[[], [0, 1, 2, 3]]))
write("FuzzSceneReader", "screenspace.json",
      json.dumps({"screenspace": True,
                  "polygons": [[[0, 0], [10, 0], [10, 10], [0, 10]], [[2, 2], [8, 3]]],
                  "are_closed": [True, False]}))
write("FuzzSceneReader", "bad-face.json", scene(points=[{"face": 8, "uv": [0.1, 0.1]}] + points,
                                                polygons=[[], [0, 1, 2]]))
write("FuzzSceneReader", "bad-json.json", '{"model": "mesh.ply", "points": [ {"face": 0, ')
write("FuzzSceneReader", "one-point-polygon.json",
      scene(points=points, polygons=[[], [0], [1, 2, 3]], shapes=[[1], [2]]))
write("FuzzSceneReader", "obj-mesh.json",
      scene(points=points[:3], polygons=[[], [0, 1, 2]]).replace("mesh.ply", "mesh.obj") +
      "\n#mesh\nv 0 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\nv 1 1 0\n"
      "f 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\nf 1 5 4\nf 2 5 1\nf 3 5 2\nf 4 5 3\n")
write("FuzzSceneReader", "binary-ply-mesh.json",
      scene(points=[{"face": 0, "uv": [0.3, 0.3]}, {"face": 1, "uv": [0.3, 0.3]},
                    {"face": 2, "uv": [0.3, 0.3]}], polygons=[[], [0, 1, 2]]).encode() +
      b"\n#mesh\n" + binary_ply("<"))
write("FuzzSceneReader", "truncated-ply-mesh.json",
      scene(points=points[:3], polygons=[[], [0, 1, 2]]).encode() + b"\n#mesh\n" +
      binary_ply(">")[:-5])
# Nesting past MaxSceneNestingDepth (256), refused by name before any value is built: 20,000
# levels of arrays in 'points' (10^5 overflowed the stack when copied), objects and both mixed
# just past the limit, and a scene whose unknown key nests exactly to the limit (read).
write("FuzzSceneReader", "deep-arrays-20000.json",
      '{"model": "mesh.ply", "points": ' + "[" * 20000 + "]" * 20000 + ', "polygons": []}')
write("FuzzSceneReader", "deep-objects-300.json",
      '{"model": "mesh.ply", "polygons": [], "points": ' + '{"p":' * 300 + "0" + "}" * 301)
write("FuzzSceneReader", "deep-mixed-300.json",
      '{"model": "mesh.ply", "polygons": [], "points": ' + '[{"p":' * 150 + "0" +
      "}]" * 150 + "}")
write("FuzzSceneReader", "nesting-at-limit.json",
      scene(points=points[:3], polygons=[[], [0, 1, 2]])[:-1] + ', "extra": ' + "[" * 255 +
      "]" * 255 + "}")

# --- SVG drawings: shapes, path commands, transforms and fill rules; nesting past
# MaxSvgNestingDepth (256) and at it; markup that is not nesting; malformed XML.
SVG_ROOT = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">'


def svg(body):
    return SVG_ROOT + body + "</svg>"


write("FuzzSvgDrawing", "paths.svg",
      svg("<path d='M10 10 h20 v20 H10 Z m40 0 l10 0 q5 5 0 10 t-5 5 c1 2 3 4 5 6 s2 2 3 3 "
          "a5 5 0 0 1 10 0 z'/>"))
write("FuzzSvgDrawing", "shapes.svg",
      svg("<g transform='translate(10 20) rotate(30) scale(2)' style='fill-rule:evenodd'>"
          "<rect x='1' y='1' width='20' height='10' rx='3'/><circle cx='50' cy='50' r='10'/>"
          "<ellipse cx='20' cy='70' rx='8' ry='4'/><line x1='0' y1='0' x2='9' y2='9'/>"
          "<polyline points='0,0 5,5 10,0'/><polygon fill-rule='nonzero' points='50,10 90,50 "
          "50,90 10,50'/></g>"))
write("FuzzSvgDrawing", "markup.svg",
      "<?xml version='1.0'?>\n<!DOCTYPE svg [ <!ENTITY e '<g></g>'> ]>\n" + SVG_ROOT +
      "<!-- <g><g> --><style><![CDATA[ <g> ]]></style><?pi <g>?><g data-x='>>'><g/>"
      "<path d='M0 0 L1 0 L1 1 Z'/></g></svg>")
write("FuzzSvgDrawing", "deep-groups-300.svg",
      svg("<g>" * 300 + "<path d='M0 0 L1 0 L1 1 Z'/>" + "</g>" * 300))
write("FuzzSvgDrawing", "nesting-at-limit.svg",
      svg("<g transform='translate(1 0)'>" * 254 + "<path d='M0 0 L1 0 L1 1 Z'/>" +
          "</g>" * 254))
write("FuzzSvgDrawing", "malformed.svg", SVG_ROOT + "<path d='M0 0 L1 1'")
