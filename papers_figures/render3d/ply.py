"""Reads the triangle meshes skelconv writes (include/skelconv/mesh/
triangle_mesh.hpp: PLY, binary little-endian or ASCII, double x y z and
optional nx ny nz, faces as 'list uchar int'). Any PLY with those elements
and scalar types is accepted; anything else is refused with a message."""
import struct

import numpy as np

TYPES = {"char": "b", "uchar": "B", "short": "h", "ushort": "H", "int": "i", "uint": "I",
         "float": "f", "double": "d", "int8": "b", "uint8": "B", "int16": "h", "uint16": "H",
         "int32": "i", "uint32": "I", "float32": "f", "float64": "d"}


class PlyError(ValueError):
    pass


def _header(handle, path):
    if handle.readline().strip() != b"ply":
        raise PlyError(f"{path}: not a PLY file")
    encoding, elements = None, []
    while True:
        line = handle.readline()
        if not line:
            raise PlyError(f"{path}: header without end_header")
        words = line.decode("ascii").split()
        if not words or words[0] == "comment":
            continue
        if words[0] == "format":
            encoding = words[1]
        elif words[0] == "element":
            elements.append((words[1], int(words[2]), []))
        elif words[0] == "property":
            elements[-1][2].append(tuple(words[1:]))
        elif words[0] == "end_header":
            break
    if encoding not in ("ascii", "binary_little_endian"):
        raise PlyError(f"{path}: unsupported format {encoding}")
    return encoding, elements


def read_ply(path):
    """(vertices N×3, normals N×3 or None, faces M×3 int) of a triangle mesh."""
    with open(path, "rb") as handle:
        encoding, elements = _header(handle, path)
        body = handle.read()
    data = {}
    if encoding == "ascii":
        tokens = iter(body.split())
        for name, count, props in elements:
            rows = []
            for _ in range(count):
                row = []
                for prop in props:
                    if prop[0] == "list":
                        n = int(next(tokens))
                        row.append([float(next(tokens)) for _ in range(n)])
                    else:
                        row.append(float(next(tokens)))
                rows.append(row)
            data[name] = (props, rows)
    else:
        offset = 0
        for name, count, props in elements:
            rows = []
            for _ in range(count):
                row = []
                for prop in props:
                    if prop[0] == "list":
                        n = struct.unpack_from("<" + TYPES[prop[1]], body, offset)[0]
                        offset += struct.calcsize(TYPES[prop[1]])
                        fmt = "<" + TYPES[prop[2]] * n
                        row.append(list(struct.unpack_from(fmt, body, offset)))
                        offset += struct.calcsize(fmt)
                    else:
                        fmt = "<" + TYPES[prop[0]]
                        row.append(struct.unpack_from(fmt, body, offset)[0])
                        offset += struct.calcsize(fmt)
                rows.append(row)
            data[name] = (props, rows)
    return _arrays(data, path)


def _arrays(data, path):
    if "vertex" not in data or "face" not in data:
        raise PlyError(f"{path}: needs 'vertex' and 'face' elements")
    props, rows = data["vertex"]
    names = [p[-1] for p in props]
    table = np.array(rows, dtype=float).reshape(len(rows), len(names))
    vertices = table[:, [names.index(c) for c in "xyz"]]
    normals = table[:, [names.index(c) for c in ("nx", "ny", "nz")]] if "nx" in names else None
    faces = [row[0] for row in data["face"][1]]
    if any(len(f) != 3 for f in faces):
        raise PlyError(f"{path}: only triangles are supported")
    faces = np.array(faces, dtype=np.int64).reshape(-1, 3)
    if faces.size and (faces.min() < 0 or faces.max() >= len(vertices)):
        raise PlyError(f"{path}: a face index is out of range")
    return vertices, normals, faces
