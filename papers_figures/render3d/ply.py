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


class _AsciiValues:
    """Values of an ASCII PLY body, one at a time."""
    def __init__(self, body):
        self.tokens = iter(body.split())

    def read(self, kind):
        return float(next(self.tokens))


class _BinaryValues:
    """Values of a binary little-endian PLY body, one at a time."""
    def __init__(self, body):
        self.body, self.offset = body, 0

    def read(self, kind):
        fmt = "<" + TYPES[kind]
        value = struct.unpack_from(fmt, self.body, self.offset)[0]
        self.offset += struct.calcsize(fmt)
        return value


def read_ply(path):
    """(vertices N×3, normals N×3 or None, faces M×3 int) of a triangle mesh."""
    with open(path, "rb") as handle:
        encoding, elements = _header(handle, path)
        body = handle.read()
    if encoding != "ascii":
        fast = _binary_fast(elements, body)
        if fast is not None:
            return _arrays(fast, path)
    values = _AsciiValues(body) if encoding == "ascii" else _BinaryValues(body)
    data = {}
    try:
        for name, count, props in elements:
            rows = []
            for _ in range(count):
                row = []
                for prop in props:
                    if prop[0] == "list":
                        n = int(values.read(prop[1]))
                        row.append([values.read(prop[2]) for _ in range(n)])
                    else:
                        row.append(values.read(prop[0]))
                rows.append(row)
            data[name] = (props, rows)
    except (StopIteration, struct.error):
        raise PlyError(f"{path}: the body has fewer values than the header announces (truncated?)") from None
    except (KeyError, ValueError) as error:
        raise PlyError(f"{path}: unreadable value or property type ({error})") from None
    return _arrays(data, path)


def _binary_fast(elements, body):
    """The layout write_mesh uses (double vertex properties, then triangles as
    'list uchar int'), read with numpy in one go; None for any other layout."""
    if [e[0] for e in elements] != ["vertex", "face"]:
        return None
    (_, nv, vprops), (_, nf, fprops) = elements
    if any(p[0] != "double" for p in vprops) or fprops != [("list", "uchar", "int", "vertex_indices")]:
        return None
    vertex_bytes = nv * 8 * len(vprops)
    face_dtype = np.dtype([("n", "u1"), ("i", "<i4", (3,))])
    if len(body) < vertex_bytes + nf * face_dtype.itemsize:
        return None
    table = np.frombuffer(body, dtype="<f8", count=nv * len(vprops)).reshape(nv, len(vprops))
    faces = np.frombuffer(body, dtype=face_dtype, count=nf, offset=vertex_bytes)
    if nf and np.any(faces["n"] != 3):
        return None
    return {"vertex": (vprops, table.tolist()), "face": (fprops, [[list(f)] for f in faces["i"]])}


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
