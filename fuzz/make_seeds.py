#!/usr/bin/env python3
"""Writes the small seed corpora of the fuzz targets into fuzz/corpus/<target>/ (committed; rerun
to regenerate). Reader seeds are tiny valid files of every format (first byte = format selector
of the target); algorithm seeds are byte strings in the decoding of fuzz_common.h."""
import os, struct

HERE = os.path.dirname(os.path.abspath(__file__))

def put(target, name, data):
    d = os.path.join(HERE, "corpus", target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())

# ---- readers (selector byte + file) ----
tet_off = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
tet_obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2/1 4\nf -4//1 -1 -2\nf 2 3 4 1\n"
ply_hdr = ("ply\nformat {}\nelement vertex 4\nproperty float x\nproperty float y\n"
           "property double z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n")
ply_ascii = ply_hdr.format("ascii 1.0") + "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n4 0 1 3 2\n"
def ply_bin(endian, fmt):
    b = ply_hdr.format(fmt).encode()
    for v in [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]:
        b += struct.pack(endian + "ffd", *v)
    b += struct.pack(endian + "B3i", 3, 0, 2, 1) + struct.pack(endian + "B4i", 4, 0, 1, 3, 2)
    return b
stl_ascii = ("solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
             "endloop\nendfacet\nendsolid t\n")
stl_bin = b"\0" * 80 + struct.pack("<I", 2)
for tri in [((0, 0, 0), (1, 0, 0), (0, 1, 0)), ((0, 0, 0), (0, 1, 0), (0, 0, 1))]:
    stl_bin += struct.pack("<3f", 0, 0, 0)
    for v in tri:
        stl_bin += struct.pack("<3f", *v)
    stl_bin += b"\0\0"

fmts_points = ["xyz", "xy", "txt", "csv", "ply", "off", "obj"]
sel = {f: bytes([i]) for i, f in enumerate(fmts_points)}
put("read_points", "xyz", sel["xyz"] + b"# c\n0 0 0\n1 2 3\r\n-1e-3 4.5e10 .5\n")
put("read_points", "xy", sel["xy"] + b"x y\n0 0\n1 2\n")
put("read_points", "csv", sel["csv"] + b"x,y,z\n0,0,0\n1;2;3\n")
put("read_points", "ply", sel["ply"] + ply_ascii.encode())
put("read_points", "off", sel["off"] + tet_off.encode())
put("read_points", "obj", sel["obj"] + tet_obj.encode())

put("read_mesh", "off", b"\0" + tet_off.encode())
put("read_mesh", "obj", b"\1" + tet_obj.encode())
put("read_mesh", "ply_ascii", b"\2" + ply_ascii.encode())
put("read_mesh", "ply_le", b"\2" + ply_bin("<", "binary_little_endian 1.0"))
put("read_mesh", "ply_be", b"\2" + ply_bin(">", "binary_big_endian 1.0"))
put("read_mesh", "stl_ascii", b"\3" + stl_ascii.encode())
put("read_mesh", "stl_bin", b"\3" + stl_bin)

put("read_polygon", "xy", b"\0" + b"0 0\n4 0\n4 4\n0 4\n\n1 1\n2 1\n2 2\n")
put("read_polygon", "geojson", b"\1" + b'{"type":"FeatureCollection","features":[{"type":"Feature",'
    b'"properties":{"a":[1,{"b":null}]},"geometry":{"type":"Polygon","coordinates":'
    b'[[[0,0],[4,0],[4,4],[0,0]],[[1,1],[1,2],[2,1],[1,1]]]}}]}')
put("read_polygon", "multi", b"\1" + b'{"type":"GeometryCollection","geometries":[{"type":'
    b'"MultiPolygon","coordinates":[[[[0,0],[1,0],[0,1],[0,0]]]]},{"type":"Point",'
    b'"coordinates":[1e300,-2.5E-3]}]}')

put("read_balls", "balls", b"x y z w\n0 0 0 1\n1,0,0,0.5\n0;1;0;-0.25\n")

# ---- algorithms (decoded by fuzz_common.h: 0x00-0x7f = grid k/8 - 8, 0x80-0x9f integers) ----
def grid(*vals):  # integer coordinates in [-16, 15] through the 0x80 band
    return bytes(0x80 + (v + 16) for v in vals)

sq = grid(0, 0, 4, 0, 4, 4, 0, 4, 2, 1, 1, 3)
cube = grid(0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 4, 4, 4, 0, 4, 0, 4, 0, 4, 4, 4, 4, 4, 1, 2, 3)
put("delaunay", "dt2", bytes([0, 6]) + sq)
put("delaunay", "dt3", bytes([1, 9]) + cube)
put("delaunay", "rt3", bytes([2, 4]) + grid(0, 0, 0, 1, 4, 0, 0, 2, 0, 4, 0, 0, 0, 0, 4, 3))
put("delaunay", "special", bytes([0, 4]) + bytes([0xc0, 0xc1, 0xe2, 0xe3, 0xa0]) + b"\0" * 8
    + grid(1, 2, 3))
put("graphs", "gamma2", bytes([0, 6, 1, 0, 10, 10, 20]) + sq)
put("graphs", "gamma3", bytes([1, 9, 0, 10, 20, 0, 0]) + cube)
put("graphs", "classic", bytes([2, 6, 2, 15]) + sq)
put("reconstruct", "r2", bytes([0, 6]) + sq)
put("reconstruct", "r3", bytes([1, 9]) + cube)
put("hal2", "square_hole", bytes([1 | 16, 4, *grid(0, 0, 8, 0, 8, 8, 0, 8), 3,
                                  *grid(2, 2, 2, 4, 4, 2), 3, *grid(1, 1, 9, 9, -1, 4)]))
put("hal2", "collinear", bytes([0, 6, *grid(0, 0, 1, 0, 2, 0, 3, 0, 3, 3, 0, 3), 2,
                                *grid(1, 0, 5, 5)]))
put("sweep", "mesh", bytes([0 | 8, 4, 4]) + grid(0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 4)
    + bytes([0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3, 2]) + grid(1, 1, 1, 9, 9, 9))
put("sweep", "polyline2", bytes([1, 4]) + grid(0, 0, 4, 0, 4, 4, 0, 4) + bytes([2])
    + grid(2, 2, 9, -3))
put("sweep", "polyline3", bytes([2 | 4, 3]) + grid(0, 0, 0, 4, 0, 0, 4, 4, 4) + bytes([1])
    + grid(1, 1, 1))
put("mesh_check", "tet", bytes([0, 4, 4]) + grid(0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 4)
    + bytes([0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3]))
put("mesh_check", "crossing", bytes([0, 6, 2]) + grid(0, 0, 0, 4, 0, 0, 0, 4, 0, 1, 1, -1, 1, 1, 1, 2, 2, 3)
    + bytes([0, 1, 2, 3, 4, 5]))

# ---- round 3 targets ----
tet_tri = bytes([0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3])
put("hausdorff", "meshes", bytes([0, 0x10 | 8, 3]) + grid(0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 4)
    + bytes([4]) + tet_tri + bytes([2]) + grid(1, 1, 1, 5, 1, 1, 1, 5, 2) + bytes([1, 0, 1, 2]))
put("hausdorff", "polyline2", bytes([1 | 4, 3, 4]) + grid(0, 0, 4, 0, 4, 4, 0, 4) + bytes([3])
    + grid(1, 1, 3, 2, 9, -3))
put("hausdorff", "polyline3", bytes([2 | 8, 0x10 | 1, 2]) + grid(0, 0, 0, 4, 4, 4) + bytes([2])
    + grid(1, 0, 0, 1, 3, 0))
put("hausdorff", "bad", bytes([0, 0, 3]) + grid(0, 0, 0, 4, 0, 0, 0, 4, 0) + bytes([0xe6, 0, 0, 1, 0, 1, 2, 0]))
put("smooth", "curve", bytes([0, 5]) + grid(0, 0, 4, 0, 5, 3, 2, 5, -1, 3))
put("smooth", "curve_hole", bytes([4 | 8 | 32, 4]) + grid(0, 0, 8, 0, 8, 8, 0, 8) + bytes([3])
    + grid(2, 2, 2, 4, 4, 2))
put("smooth", "curve_spike", bytes([0, 4]) + grid(0, 0, 4, 0, 2, 0, 0, 4))
put("smooth", "tet_split", bytes([1, 0]) + bytes(12))
put("smooth", "octa_pn", bytes([1 | 8, 1]) + bytes(18))
put("smooth", "stellated", bytes([1 | 16 | 128, 2, 0x5a]) + bytes([3, 0x41, 7] * 14))
put("smooth", "flipped", bytes([1 | 4, 1]) + bytes(18) + bytes([1 | 8]))
put("hal3", "tet", bytes([2, 0]) + bytes(12) + bytes([0, 4, 0]) + grid(0, 0, 0) + bytes([1, 2, 3]))
put("hal3", "octa", bytes([2 | 4, 1]) + bytes(18) + bytes([1, 8, 0]) + grid(0, 0, 0) + bytes([0])
    + grid(5, 5, 5) + bytes([5, 6, 7, 0x0b, 0x11, 0x42]) + bytes([1]) + bytes(18) + bytes([0]))
put("hal3", "stellated", bytes([2, 2, 0x5a]) + bytes([3, 0x41, 7] * 14) + bytes([2, 6, 0])
    + grid(0, 0, 0) + bytes([1, 2, 3, 0x0d, 0x22]))
put("hal3", "perturbed", bytes([2 | 4, 3, 0xff]) + bytes([0x44, 0x3c, 0x41, 0x40, 0x47] * 9)
    + bytes([1, 3, 0]) + grid(1, 0, 0) + bytes([5, 9]) + bytes([4 | 1, 0x10]) + bytes(15))
put("hal3", "flipped", bytes([1, 1]) + bytes(18) + bytes([1 | 8, 0]))
def ball(x, y, z, w):  # w: 1..16 quarter units
    return grid(x, y, z) + bytes([w - 1])
put("skin", "one", bytes([0, 1]) + ball(0, 0, 0, 4))
put("skin", "two", bytes([1, 2]) + ball(0, 0, 0, 4) + ball(1, 0, 0, 4))
put("skin", "three", bytes([2, 3]) + ball(0, 0, 0, 4) + ball(2, 0, 0, 8)
    + ball(0, 2, 0, 2))
put("skin", "cell", bytes([8, 2]) + ball(0, 0, 0, 16) + ball(3, 0, 0, 16) + bytes([3]))
put("skin", "bad_t", bytes([7, 1]) + ball(0, 0, 0, 4))
put("skin", "negative", bytes([0, 2]) + ball(0, 0, 0, 0x11) + ball(1, 1, 1, 0x12))
put("render", "svg_all", bytes([0, 1, 6]) + bytes([0 | 8 * 2]) + grid(0, 0, 4, 0, 2, 3)
    + bytes([1 | 8 * 3 | 0x80]) + grid(0, 0, 4, 0, 4, 4, 0, 4) + bytes([2 | 8 * 2]) + grid(0, 0, 4, 0, 2, 3)
    + bytes([5 | 8 * 1]) + grid(1, 1, 2, 2) + bytes([6 | 8 * 1 | 0x80]) + grid(1, 2, 3, 3)
    + bytes([7 | 8 * 3]) + grid(0, 0, 1, 2, 3, 2, 4, 0))
put("render", "svg_disc_edges", bytes([0, 0, 2]) + bytes([4 | 8]) + grid(1, 1, 3, 3)
    + bytes([3 | 8 * 3]) + grid(0, 0, 1, 0, 1, 1, 0, 1))
put("render", "svg_huge", bytes([0, 0, 2]) + bytes([0 | 8]) + bytes([0xe2, 0xe3, 0xc0, 0xc1]))
put("render", "raster_mesh", bytes([1, 15, 15, 20, 140, 3, 4]) + grid(0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 4)
    + tet_tri + bytes([0x33]) + grid(1, 2, 3, 4) + bytes([1]) + grid(0, 0, 0, 2) + bytes([1]) + grid(5, 5, 5))
put("render", "raster_ortho", bytes([1, 0x80 | 9, 0x80 | 7, 0, 128, 2, 1, 0, 1, 2]) + grid(0, 0, 0, 4, 0, 0, 0, 4, 0)
    + bytes([0x30, 0, 0]))
