#!/usr/bin/env python3
"""A scan thinned by space, for measuring a cost per drawn point at a fixed splat size
(lab/scripts/web_point_cost.py, docs/web.md "Frame time").

usage: lab/scripts/thinned_scan.py SCAN.pcd OUT.pcd FRACTION X0,Y0,Z0,X1,Y1,Z1 CX,CY,CZ,EDGE

Reads a PCD (fields x y z rgba, DATA binary or binary_compressed: PCL's LZF), keeps the points
inside the box (octopoint-prepare's --crop: scan units, inclusive) and of those the ones whose
cell is among the FRACTION (0..1] of cells a fixed hash picks, and writes them as an unorganized
binary PCD. The cells are the voxels of depth 4 of the cube the whole scan is fitted to (its
lowest corner and edge in scan units, as `octopoint-render --file M.oct --info` prints them). The
points at each end of each axis are always kept, so that every fraction fits the same cube:
octopoint-prepare then puts the kept points in the same voxels as the whole scan's, the splats keep
their size, and only their number falls; each kept cell is a whole subtree of the whole scan's
model, so that every depth keeps about the same share and the depths stay densely sampled
(renderer/level_of_detail.h: depth auto still draws the finest). The cells a smaller fraction
keeps are kept by every larger one (the models nest).
"""
import struct
import sys


def lzf_decompress(data, size):
    """PCL's binary_compressed payload: LibLZF's format (literal runs and back references)."""
    out = bytearray()
    i = 0
    while i < len(data):
        control = data[i]
        i += 1
        if control < 32:  # a literal run of control + 1 bytes
            out += data[i:i + control + 1]
            i += control + 1
            continue
        length = control >> 5
        if length == 7:
            length += data[i]
            i += 1
        start = len(out) - ((control & 0x1F) << 8) - data[i] - 1
        i += 1
        length += 2
        if start < 0:
            sys.exit("thinned_scan: a back reference before the start of the data")
        for k in range(length):  # byte by byte: the reference may overlap what it writes
            out.append(out[start + k])
    if len(out) != size:
        sys.exit("thinned_scan: %d bytes decompressed, the header said %d" % (len(out), size))
    return bytes(out)


def read_pcd(path):
    """The points as (x, y, z, rgba) tuples."""
    with open(path, "rb") as scan:
        header = {}
        while True:
            line = scan.readline()
            if not line:
                sys.exit("thinned_scan: %s: no DATA line" % path)
            words = line.decode("ascii").split()
            if not words or words[0].startswith("#"):
                continue
            header[words[0]] = words[1:]
            if words[0] == "DATA":
                break
        body = scan.read()
    if header.get("FIELDS") != ["x", "y", "z", "rgba"] or header.get("SIZE") != ["4"] * 4:
        sys.exit("thinned_scan: %s: fields must be x y z rgba of 4 bytes" % path)
    count = int(header["POINTS"][0])
    kind = header["DATA"][0]
    if kind == "binary_compressed":
        packed, size = struct.unpack_from("<II", body)
        columns = lzf_decompress(body[8:8 + packed], size)  # field after field
        xs, ys, zs = (struct.unpack_from("<%df" % count, columns, f * 4 * count) for f in range(3))
        rgba = struct.unpack_from("<%dI" % count, columns, 12 * count)
        return list(zip(xs, ys, zs, rgba))
    if kind == "binary":
        return list(struct.iter_unpack("<fffI", body[:16 * count]))
    sys.exit("thinned_scan: %s: DATA %s is not read here" % (path, kind))


CELLS_A_SIDE = 16  # depth 4


def cell_rank(point, cube):
    """Where the cell of `point` falls in 0..9999 under a fixed spatial hash."""
    cell = cube[3] / CELLS_A_SIDE
    ix, iy, iz = (min(CELLS_A_SIDE - 1, int((point[a] - cube[a]) // cell)) & 0xFFFFFFFF
                  for a in range(3))
    mixed = (ix * 73856093 ^ iy * 19349663 ^ iz * 83492791) & 0xFFFFFFFF
    mixed = (mixed * 2654435761) & 0xFFFFFFFF  # Knuth's multiplier spreads the low bits
    return (mixed >> 8) % 10000


def thin(points, fraction, box, cube):
    x0, y0, z0, x1, y1, z1 = box
    inside = [p for p in points if x0 <= p[0] <= x1 and y0 <= p[1] <= y1 and z0 <= p[2] <= z1]
    if not inside:
        sys.exit("thinned_scan: no point inside the box")
    ends = set()
    for axis in range(3):
        ends.add(min(range(len(inside)), key=lambda k: inside[k][axis]))
        ends.add(max(range(len(inside)), key=lambda k: inside[k][axis]))
    limit = fraction * 10000
    return [p for k, p in enumerate(inside)
            if k in ends or cell_rank(p, cube) < limit]


def write_pcd(path, points):
    with open(path, "wb") as out:
        out.write(("# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z rgba\n"
                   "SIZE 4 4 4 4\nTYPE F F F U\nCOUNT 1 1 1 1\nWIDTH %d\nHEIGHT 1\n"
                   "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS %d\nDATA binary\n" %
                   (len(points), len(points))).encode("ascii"))
        out.write(b"".join(struct.pack("<fffI", *p) for p in points))


def main():
    if len(sys.argv) != 6:
        sys.exit(__doc__.split("\n\n")[1])
    fraction = float(sys.argv[3])
    box = [float(v) for v in sys.argv[4].split(",")]
    cube = [float(v) for v in sys.argv[5].split(",")]
    if not 0 < fraction <= 1 or len(box) != 6 or len(cube) != 4 or cube[3] <= 0:
        sys.exit(__doc__.split("\n\n")[1])
    kept = thin(read_pcd(sys.argv[1]), fraction, box, cube)
    write_pcd(sys.argv[2], kept)
    print("thinned_scan: %d points kept (fraction %g)" % (len(kept), fraction))


if __name__ == "__main__":
    main()
