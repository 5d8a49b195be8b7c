"""The `skelconv` Python module against the `skelconv` command on the same inputs.

Run by ctest (python/CMakeLists.txt) with PYTHONPATH holding the built module,
SKELCONV_CLI the command and SKELCONV_TEST_DATA tests/data. The module and the
command share the library, so f, grad f, enclosures and meshes must agree bit
for bit (the CLI prints %.17g, which round-trips a double), and every error
must carry the CLI's message: what these tests check is the binding itself
(array layout, conversions, errors), the values are tested in C++.
"""
import glob
import json
import math
import os
import subprocess
import tempfile
import threading
import unittest

import numpy as np

import skelconv

CLI = os.environ["SKELCONV_CLI"]
DATA = os.environ["SKELCONV_TEST_DATA"]
ERROR_PREFIX = "skelconv: error: "


def run_cli(*args, stdin=""):
    """(exit status, stdout, the error message without its prefix)."""
    done = subprocess.run([CLI, *args], input=stdin, capture_output=True, text=True, check=False)
    message = done.stderr.strip()
    if message.startswith(ERROR_PREFIX):
        message = message[len(ERROR_PREFIX):]
    return done.returncode, done.stdout, message


def rows_text(array):
    return "".join(" ".join(repr(float(x)) for x in row) + "\n" for row in array)


def cli_numbers(text, columns):
    values = [float(x) for line in text.splitlines() for x in line.split()[:columns]]
    return np.array(values).reshape(-1, columns)


def random_points(skeleton_path, count, seed):
    """Points around the skeleton: its skeleton points' box, widened by 1."""
    rng = np.random.default_rng(seed)
    corners = []
    with open(skeleton_path, encoding="utf-8") as f:
        text = f.read()
    for token in json.loads(text).get("primitives", []):
        corners.extend(_numbers_of(token))
    xyz = np.array(corners[: len(corners) // 3 * 3]).reshape(-1, 3) if corners else np.zeros((1, 3))
    lo, hi = xyz.min(axis=0) - 1.0, xyz.max(axis=0) + 1.0
    return lo + (hi - lo) * rng.random((count, 3))


def _numbers_of(node):
    """The coordinates in a primitive or blend node (a, b, center, vertices)."""
    out = []
    if isinstance(node, dict):
        for key in ("a", "b", "center"):
            if key in node:
                out.extend(node[key])
        for vertex in node.get("vertices", []):
            out.extend(vertex)
        for child in node.get("children", []):
            out.extend(_numbers_of(child))
    return out


GOOD = sorted(glob.glob(os.path.join(DATA, "good", "*.json"))) + [os.path.join(DATA, "mesh", "ring.json")]


class FieldAgreesWithCli(unittest.TestCase):
    def test_every_good_skeleton(self):
        for k, path in enumerate(GOOD):
            with self.subTest(skeleton=os.path.basename(path)):
                points = random_points(path, 300, seed=k)
                # field's default tolerance is eval's --tolerance (docs/field.md, "Tolerance").
                status, out, message = run_cli("eval", path, "--tolerance", "1e-12", stdin=rows_text(points))
                self.assertEqual(status, 0, message)
                expected = cli_numbers(out, 4)
                f, grad = skelconv.load_skeleton_file(path).field(points)
                self.assertEqual(f.shape, (300,))
                self.assertEqual(grad.shape, (300, 3))
                self.assertEqual(f.dtype, np.float64)
                np.testing.assert_array_equal(f, expected[:, 0])
                np.testing.assert_array_equal(grad, expected[:, 1:])

    def test_one_point_and_thread_counts(self):
        path = os.path.join(DATA, "good", "three_primitives.json")
        skeleton = skelconv.load_skeleton_file(path)
        points = random_points(path, 1000, seed=7)
        f1, g1 = skeleton.field(points, threads=1)
        f2, g2 = skeleton.field(points, threads=3)
        np.testing.assert_array_equal(f1, f2)
        np.testing.assert_array_equal(g1, g2)
        # An absurd count is refused with the limit (it started what the system allowed).
        with self.assertRaisesRegex(skelconv.InputError, r"^threads: at most 1024 threads \(0: every core, [0-9]+ here\), got 100000$"):
            skeleton.field(points, threads=100000)
        f, g = skeleton.value_and_gradient(points[5])
        self.assertEqual(f, f1[5])
        np.testing.assert_array_equal(g, g1[5])

    def test_points_are_converted(self):
        path = os.path.join(DATA, "good", "inverse_segment.json")
        skeleton = skelconv.load_skeleton_file(path)
        points = random_points(path, 10, seed=3)
        f, g = skeleton.field(points)
        f_list, g_list = skeleton.field(points.tolist())           # a list of lists
        f_strided, _ = skeleton.field(np.asfortranarray(points))   # another memory layout
        np.testing.assert_array_equal(f, f_list)
        np.testing.assert_array_equal(g, g_list)
        np.testing.assert_array_equal(f, f_strided)
        self.assertEqual(skeleton.field(np.zeros((0, 3)))[0].shape, (0,))

    def test_concurrent_calls_from_python_threads(self):
        # field() releases the GIL: Python threads evaluate at the same time
        # and each gets its own, correct, result.
        path = os.path.join(DATA, "mesh", "ring.json")
        skeleton = skelconv.load_skeleton_file(path)
        points = random_points(path, 2000, seed=11)
        expected = skeleton.field(points, threads=1)[0]
        results = [None] * 4

        def work(k):
            results[k] = skeleton.field(points, threads=1)[0]

        threads = [threading.Thread(target=work, args=(k,)) for k in range(4)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        for r in results:
            np.testing.assert_array_equal(r, expected)


class SkeletonFromText(unittest.TestCase):
    def test_parse_json_and_python_objects_equal_the_file(self):
        path = os.path.join(DATA, "good", "blend_tree.json")
        with open(path, encoding="utf-8") as f:
            text = f.read()
        data = json.loads(text)
        points = random_points(path, 50, seed=5)
        expected = skelconv.load_skeleton_file(path).field(points)
        from_text = skelconv.parse_skeleton_json(text).field(points)
        from_objects = skelconv.Skeleton(data).field(points)
        for got in (from_text, from_objects):
            np.testing.assert_array_equal(got[0], expected[0])
            np.testing.assert_array_equal(got[1], expected[1])

    def test_list_of_primitives_with_numpy_numbers(self):
        segment = {"type": "segment", "a": np.array([0.0, 0.0, 0.0]), "b": np.array([1.0, 0.0, 0.0]),
                   "kernel": {"family": "cauchy", "degree": 4, "s": np.float64(2.0)}}
        skeleton = skelconv.Skeleton([segment])
        self.assertEqual(len(skeleton), 1)
        self.assertEqual(skeleton.iso, 1.0)
        text = '{"primitives": [{"type": "segment", "a": [0,0,0], "b": [1,0,0], ' \
               '"kernel": {"family": "cauchy", "degree": 4, "s": 2}}]}'
        p = np.array([[0.5, 0.3, 0.1]])
        self.assertEqual(skeleton.field(p)[0][0], skelconv.parse_skeleton_json(text).field(p)[0][0])
        self.assertEqual(len(skelconv.Skeleton()), 0)


PRIMITIVE_CLASSES = {"segment": skelconv.Segment, "polygon": skelconv.Polygon,
                     "scalis_segment": skelconv.ScalisSegment, "scalis_triangle": skelconv.ScalisTriangle,
                     "point": skelconv.Point}


def node_from_file_object(node):
    """The module's object for one primitive or blend node of a skeleton file."""
    fields = dict(node)
    if "blend" in fields:
        kind = fields.pop("blend")
        children = [node_from_file_object(child) for child in fields.pop("children")]
        return skelconv.Blend(kind, children, **fields)
    return PRIMITIVE_CLASSES[fields.pop("type")](**fields)


class PrimitivesFromPythonValues(unittest.TestCase):
    def test_every_good_skeleton_rebuilt_from_objects(self):
        # Each file's primitives and blend nodes made by the module's classes:
        # the field equals the command's on the file itself.
        for k, path in enumerate(GOOD):
            with self.subTest(skeleton=os.path.basename(path)):
                with open(path, encoding="utf-8") as f:
                    data = json.load(f)
                nodes = [node_from_file_object(node) for node in data["primitives"]]
                skeleton = skelconv.Skeleton(nodes, iso=data.get("iso"))
                self.assertEqual(skeleton.iso, data.get("iso", 1))
                points = random_points(path, 100, seed=100 + k)
                status, out, message = run_cli("eval", path, stdin=rows_text(points))
                self.assertEqual(status, 0, message)
                expected = cli_numbers(out, 4)
                f, grad = skeleton.field(points)
                np.testing.assert_array_equal(f, expected[:, 0])
                np.testing.assert_array_equal(grad, expected[:, 1:])
                self.assertEqual([n.data for n in nodes], data["primitives"])

    def test_numpy_values_and_repr(self):
        segment = skelconv.Segment(np.zeros(3), np.array([1.0, 0, 0]),
                                   {"family": "cauchy", "degree": np.int64(4), "s": np.float32(2)}, weight=[1, 0.5])
        self.assertEqual(segment.data, {"type": "segment", "a": [0.0, 0.0, 0.0], "b": [1.0, 0.0, 0.0],
                                        "kernel": {"family": "cauchy", "degree": 4, "s": 2.0}, "weight": [1, 0.5]})
        self.assertTrue(repr(segment).startswith('skelconv.Segment({"type": "segment"'))
        self.assertIsInstance(segment, skelconv.Node)
        blend = skelconv.Blend("union", [segment, skelconv.Point([2, 0, 0], {"family": "soft", "R": 1.5})])
        self.assertEqual(len(skelconv.Skeleton([blend])), 2)
        self.assertEqual(len(skelconv.Skeleton(segment)), 1)

    def test_errors_are_the_readers_at_the_argument(self):
        # compact_R_negative.json's third segment, made alone: the file's
        # message, located at the argument instead of the file's path.
        path = os.path.join(DATA, "bad", "compact_R_negative.json")
        _, _, message = run_cli("eval", path, stdin="0 0 0\n")
        prefix = path + ": primitives[2]."
        self.assertTrue(message.startswith(prefix), message)
        with self.assertRaises(skelconv.InputError) as raised:
            skelconv.Segment([0, 2, 0], [1, 2, 1], {"family": "compact", "degree": 6, "R": -1})
        self.assertEqual(str(raised.exception), message[len(prefix):])
        with self.assertRaises(skelconv.InputError) as raised:
            skelconv.Blend("super_elliptic", [skelconv.Point([0, 0, 0], {"family": "soft", "R": 1})], t=0, r=1)
        self.assertEqual(str(raised.exception), "t: must be > 0, got 0")
        # A nan is refused at its argument, as the reader refuses one in a
        # file (json.dumps would write NaN: "malformed JSON" at a column of
        # text the caller never wrote).
        with self.assertRaises(skelconv.InputError) as raised:
            skelconv.Segment([0, np.nan, 0], [1, 2, 1], {"family": "compact", "degree": 6, "R": 1})
        self.assertEqual(str(raised.exception), "a[1]: must be finite, got nan")
        with self.assertRaises(skelconv.InputError) as raised:
            skelconv.Skeleton({"primitives": [{"type": "point", "center": [0, 0, 0],
                                               "kernel": {"family": "soft", "R": np.float32("inf")}}]})
        self.assertEqual(str(raised.exception), "primitives[0].kernel.R: must be finite, got inf")
        with self.assertRaises(skelconv.InputError) as raised:
            skelconv.Point([0, 0, 0], {"family": "soft", "R": 1, "s": 2})
        self.assertEqual(str(raised.exception), 'kernel: unknown field "s" for the soft family (allowed: "family", "R")')


def printable(text):
    """The message as the CLI prints it: control characters (but tab) as \\xNN
    (src/cli/exit_status.hpp), so that its line stays one line."""
    return "".join(f"\\x{ord(c):02x}" if (ord(c) < 0x20 and c != "\t") or ord(c) == 0x7F else c for c in text)


class ErrorsCarryTheCliMessage(unittest.TestCase):
    def test_every_bad_skeleton_file(self):
        bad = sorted(glob.glob(os.path.join(DATA, "bad", "*.json")))
        self.assertGreater(len(bad), 20)
        for path in bad:
            with self.subTest(skeleton=os.path.basename(path)):
                status, _, message = run_cli("eval", path, stdin="0 0 0\n")
                self.assertEqual(status, 2)
                with self.assertRaises(skelconv.InputError) as raised:
                    skelconv.load_skeleton_file(path)
                self.assertEqual(printable(str(raised.exception)), message)
                self.assertIsInstance(raised.exception, ValueError)
                # The same text parsed from a string: the message without the file name.
                with open(path, encoding="utf-8", errors="replace") as f:
                    text = f.read()
                with self.assertRaises(skelconv.InputError) as parsed:
                    skelconv.parse_skeleton_json(text)
                self.assertEqual(path + ": " + printable(str(parsed.exception)), message)

    def test_missing_file(self):
        path = os.path.join(DATA, "no_such_file.json")
        _, _, message = run_cli("eval", path)
        with self.assertRaises(skelconv.InputError) as raised:
            skelconv.load_skeleton_file(path)
        self.assertEqual(str(raised.exception), message)

    def test_a_bad_point_is_located_at_its_row(self):
        # The CLI rejects "1 nan 2" when it reads the line; the module gets
        # the double and the library rejects it, at the row.
        path = os.path.join(DATA, "good", "three_primitives.json")
        with self.assertRaises(skelconv.InputError) as raised:
            skelconv.load_skeleton_file(path).field(np.array([[0, 0, 1], [1, np.nan, 2]]))
        self.assertEqual(str(raised.exception), "points[1]: query point must be finite, got (1, nan, 2)")

    def test_an_evaluation_failure(self):
        # As tests/CMakeLists.txt eval.first_failure_is_an_evaluation: exit 1.
        path = os.path.join(DATA, "good", "points.json")
        status, _, message = run_cli("eval", path, stdin="0 0 1\n0 10 1e-110\n")
        self.assertEqual(status, 1)
        with self.assertRaises(skelconv.EvaluationError) as raised:
            skelconv.load_skeleton_file(path).field([[0, 0, 1], [0, 10, 1e-110]])
        self.assertIsInstance(raised.exception, ArithmeticError)
        self.assertEqual(str(raised.exception), "points[1]: " + message[len("line 2: "):])

    def test_wrong_shapes(self):
        skeleton = skelconv.load_skeleton_file(os.path.join(DATA, "good", "inverse_segment.json"))
        for bad, shape in ((np.zeros(3), "(3,)"), (np.zeros((4, 2)), "(4, 2)")):
            with self.assertRaises(skelconv.InputError) as raised:
                skeleton.field(bad)
            self.assertEqual(str(raised.exception), f"points: must be an (N, 3) array of numbers, got shape {shape}")
        with self.assertRaises(skelconv.InputError) as raised:
            skeleton.bound(np.zeros((2, 3)))
        self.assertEqual(str(raised.exception), "boxes: must be an (N, 6) array of numbers, got shape (2, 3)")


class BoundAgreesWithCli(unittest.TestCase):
    def test_enclosures_and_a_bad_box(self):
        path = os.path.join(DATA, "good", "three_primitives.json")
        rng = np.random.default_rng(2)
        lo = random_points(path, 40, seed=2)
        boxes = np.hstack([lo, lo + rng.random((40, 3))])
        status, out, message = run_cli("bound", path, stdin=rows_text(boxes))
        self.assertEqual(status, 0, message)
        expected = cli_numbers(out, 2)
        got_lo, got_hi = skelconv.load_skeleton_file(path).bound(boxes)
        np.testing.assert_array_equal(got_lo, expected[:, 0])
        np.testing.assert_array_equal(got_hi, expected[:, 1])
        flipped = np.array([[0, 0, 0, 1, 1, 1], [1, 0, 0, 0, 1, 1]], dtype=float)
        _, _, message = run_cli("bound", path, stdin=rows_text(flipped))
        with self.assertRaises(skelconv.InputError) as raised:
            skelconv.load_skeleton_file(path).bound(flipped)
        self.assertEqual(str(raised.exception), "boxes[1]: " + message[len("line 2: "):])


class NoNegativeZero(unittest.TestCase):
    def test_bound_of_a_box_straddling_a_support(self):
        # The enclosure's lower end comes out of directed rounding as -0 (the
        # CLI's test bound.straddling_support prints "0 0.13099298158710004").
        skeleton = skelconv.load_skeleton_file(os.path.join(DATA, "notes_soft_points.json"))
        lo, hi = skeleton.bound([[2, 2, 2, 3, 3, 3]])
        self.assertEqual(lo[0], 0.0)
        self.assertFalse(math.copysign(1.0, lo[0]) < 0, "lo is -0")
        self.assertEqual(hi[0], 0.13099298158710004)

    def test_field_zeros_unsigned_negative_subnormal_kept(self):
        # A compact point beyond its support: f and grad exactly 0, all +0;
        # a negative Gaussian point 27 widths out: f a negative subnormal.
        skeleton = skelconv.parse_skeleton_json(
            '{"primitives": [{"type": "point", "center": [0, 0, 0], "kernel": {"family": "compact", "degree": 4, "R": 1}}]}')
        f, g = skeleton.field([[5, -5, 0], [0, -3, 0]])
        for value in list(f) + list(g.ravel()):
            self.assertFalse(math.copysign(1.0, value) < 0, f"{value} is -0")
        gaussian = skelconv.parse_skeleton_json(
            '{"primitives": [{"type": "point", "center": [0, 0, 0], "kernel": {"family": "gaussian", "a": 1, "b": 1}, "weight": -1}]}')
        f, _ = gaussian.field([[27, 0, 0]])
        self.assertLess(f[0], 0.0)


class BoundIsoAndOctreeAgreeWithCli(unittest.TestCase):
    def test_classification(self):
        path = os.path.join(DATA, "good", "three_primitives.json")
        rng = np.random.default_rng(4)
        lo = random_points(path, 60, seed=4)
        boxes = np.hstack([lo, lo + 0.5 * rng.random((60, 3))])
        status, out, message = run_cli("bound", path, "--iso", "0.3", stdin=rows_text(boxes))
        self.assertEqual(status, 0, message)
        got_lo, got_hi, labels = skelconv.load_skeleton_file(path).bound(boxes, iso=0.3)
        expected = [line.split() for line in out.splitlines()]
        np.testing.assert_array_equal(got_lo, [float(e[0]) for e in expected])
        np.testing.assert_array_equal(got_hi, [float(e[1]) for e in expected])
        self.assertEqual(list(labels), [e[2] for e in expected])
        self.assertEqual(len(set(labels)), 3, "every classification occurs")

    def test_octree(self):
        path = os.path.join(DATA, "mesh", "ring.json")
        box = [-2.5, -2.5, -1.5, 2.5, 2.5, 1.5]
        status, out, message = run_cli("bound", path, "--octree", "4", "--iso", "0.38", "--box", *map(str, box))
        self.assertEqual(status, 0, message)
        expected = np.array([[int(x) for x in line.split()[1:]] for line in out.splitlines()])
        got = skelconv.load_skeleton_file(path).octree(box, 4, iso=0.38)
        self.assertEqual(got.shape, (5, 3))
        np.testing.assert_array_equal(got, expected)

    def test_bad_octree_arguments(self):
        path = os.path.join(DATA, "mesh", "ring.json")
        skeleton = skelconv.load_skeleton_file(path)
        box = ["0", "0", "0", "1", "1", "1"]
        _, _, message = run_cli("bound", path, "--octree", "11", "--box", *box)
        with self.assertRaises(skelconv.InputError) as raised:
            skeleton.octree([0, 0, 0, 1, 1, 1], 11)
        self.assertEqual("--octree: " + str(raised.exception)[len("depth: "):], message)
        _, _, message = run_cli("bound", path, "--octree", "2", "--box", "1", "0", "0", "0", "1", "1")
        with self.assertRaises(skelconv.InputError) as raised:
            skeleton.octree([1, 0, 0, 0, 1, 1], 2)
        self.assertEqual("--" + str(raised.exception), message)
        _, _, message = run_cli("bound", path, "--iso", "inf", stdin="0 0 0 1 1 1\n")
        with self.assertRaises(skelconv.InputError) as raised:
            skeleton.bound([[0, 0, 0, 1, 1, 1]], iso=float("inf"))
        self.assertEqual("--" + str(raised.exception), message)


def read_ascii_ply(path):
    with open(path, encoding="ascii") as f:
        lines = f.read().splitlines()
    vertices = int(next(l for l in lines if l.startswith("element vertex")).split()[2])
    start = lines.index("end_header") + 1
    v = np.array([[float(x) for x in l.split()] for l in lines[start:start + vertices]])
    t = np.array([[int(x) for x in l.split()[1:]] for l in lines[start + vertices:] if l.strip()])
    return v[:, :3], t, v[:, 3:6]


class MeshAgreesWithCli(unittest.TestCase):
    def test_grid_and_cgal_meshes(self):
        path = os.path.join(DATA, "mesh", "ring.json")
        skeleton = skelconv.load_skeleton_file(path)
        for method, size in (("grid", "0.1"), ("cgal", "0.15")):
            with self.subTest(method=method), tempfile.TemporaryDirectory() as tmp:
                ply = os.path.join(tmp, "ring.ply")
                status, _, message = run_cli("mesh", path, "--iso", "0.38", "--method", method, "--size", size,
                                             "--ascii", "--quiet", "-o", ply)
                self.assertEqual(status, 0, message)
                vertices, triangles, normals = skeleton.mesh(iso=0.38, method=method, size=float(size))
                expected = read_ascii_ply(ply)
                self.assertGreater(len(triangles), 100)
                self.assertEqual(triangles.dtype, np.int32)
                np.testing.assert_array_equal(vertices, expected[0])
                np.testing.assert_array_equal(triangles, expected[1])
                np.testing.assert_array_equal(normals, expected[2])

    def test_grid_warns_of_a_missed_part(self):
        # The command's warning for a blob thinner than the grid spacing
        # (tests/CMakeLists.txt, cli.mesh.grid_missed_blob), as a
        # RuntimeWarning: the mesh is still returned, the same as the
        # command's.
        path = os.path.join(DATA, "mesh", "blobs.json")
        skeleton = skelconv.load_skeleton_file(path)
        with tempfile.TemporaryDirectory() as tmp:
            status, _, message = run_cli("mesh", path, "--iso", "0.5", "--method", "grid", "--quiet",
                                         "-o", os.path.join(tmp, "blobs.ply"))
        self.assertEqual(status, 0, message)
        printed = message.strip().removeprefix("skelconv mesh: warning: --size ")
        with self.assertWarns(RuntimeWarning) as caught:
            vertices, triangles, _ = skeleton.mesh(iso=0.5, method="grid")
        self.assertEqual(str(caught.warning), "size=" + printed)
        self.assertIn("needs --size 0.041 or less", str(caught.warning))
        self.assertGreater(len(triangles), 100)

    def test_topology_and_max_triangles(self):
        path = os.path.join(DATA, "mesh", "ring.json")
        skeleton = skelconv.load_skeleton_file(path)
        with tempfile.TemporaryDirectory() as tmp:
            status, out, message = run_cli("mesh", path, "--iso", "0.38", "--size", "0.2", "--quiet",
                                           "-o", os.path.join(tmp, "ring.ply"))
        self.assertEqual(status, 0, message)
        printed = dict(line.split(": ", 1) for line in out.splitlines())
        vertices, triangles, _ = skeleton.mesh(iso=0.38, size=0.2)
        topology = skelconv.mesh_topology(vertices, triangles)
        for key in ("triangles", "vertices", "components", "euler_characteristic"):
            self.assertEqual(str(topology[key]), printed[key], key)
        for key in ("closed", "manifold"):
            self.assertEqual("yes" if topology[key] else "no", printed[key], key)
        self.assertEqual(topology["euler_characteristic"], 0)  # a torus
        _, _, message = run_cli("mesh", path, "--iso", "0.38", "--size", "0.01", "--max-triangles", "1000",
                                "--quiet", "-o", os.path.join(DATA, "unused.ply"))
        with self.assertRaises(skelconv.InputError) as raised:
            skeleton.mesh(iso=0.38, size=0.01, max_triangles=1000)
        # The library locates it at the option, "--size"; the module at the argument.
        self.assertEqual("--" + str(raised.exception), message)

    def test_no_surface(self):
        path = os.path.join(DATA, "mesh", "ring.json")
        _, _, message = run_cli("mesh", path, "--iso", "1000", "--quiet", "-o", os.path.join(DATA, "unused.ply"))
        with self.assertRaises(skelconv.InputError) as raised:
            skelconv.load_skeleton_file(path).mesh(iso=1000)
        self.assertEqual("--" + str(raised.exception), message)

    def test_bad_topology_input(self):
        with self.assertRaises(skelconv.InputError) as raised:
            skelconv.mesh_topology(np.zeros((3, 3)), [[0, 1, 3]])
        self.assertEqual(str(raised.exception), "triangles[0]: vertex index 3 outside [0, 3)")

    def test_bad_method(self):
        skeleton = skelconv.load_skeleton_file(os.path.join(DATA, "mesh", "ring.json"))
        with self.assertRaises(skelconv.InputError) as raised:
            skeleton.mesh(iso=0.38, method="marching")
        # The CLI says "--method: marching not in {cgal,grid}".
        self.assertEqual(str(raised.exception), "method: marching not in {cgal,grid}")


PLY_TYPES = {"float": "<f4", "double": "<f8", "int": "<i4", "uchar": "u1", "uint": "<u4"}


def read_ply_or_off(path):
    """Vertices (V, 3) and triangles (T, 3) of an OFF or PLY file of triangles
    (ASCII, or binary little-endian with one vertex element of scalar properties)."""
    with open(path, "rb") as f:
        data = f.read()
    if not data.startswith(b"ply"):
        lines = [l.split(b"#")[0].split() for l in data.splitlines()]
        lines = [l for l in lines if l]
        assert lines[0] == [b"OFF"]
        v, t = int(lines[1][0]), int(lines[1][1])
        vertices = np.array([[float(x) for x in l[:3]] for l in lines[2:2 + v]])
        return vertices, np.array([[int(x) for x in l[1:4]] for l in lines[2 + v:2 + v + t]])
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = [l.split() for l in data[:end].decode("ascii").splitlines()]
    v = int(next(l for l in header if l[:2] == ["element", "vertex"])[2])
    t = int(next(l for l in header if l[:2] == ["element", "face"])[2])
    if ["format", "ascii", "1.0"] in header:
        body = [l.split() for l in data[end:].decode("ascii").splitlines() if l.strip()]
        vertices = np.array([[float(x) for x in l[:3]] for l in body[:v]])
        return vertices, np.array([[int(x) for x in l[1:4]] for l in body[v:v + t]])
    first_face = next(k for k, l in enumerate(header) if l[:2] == ["element", "face"])
    properties = [l for l in header if l[0] == "property"]
    vertex_type = np.dtype([(l[2], PLY_TYPES[l[1]]) for l in header[:first_face] if l[0] == "property"])
    _, _, count, index, _ = next(l for l in header[first_face:] if l[:2] == ["property", "list"])
    face_type = np.dtype([("n", PLY_TYPES[count]), ("i", PLY_TYPES[index], 3)])
    assert len(properties) == len(vertex_type.names) + 1, "one vertex element, then the faces"
    vertex_rows = np.frombuffer(data, vertex_type, v, end)
    faces = np.frombuffer(data, face_type, t, end + v * vertex_type.itemsize)
    assert (faces["n"] == 3).all()
    return np.stack([vertex_rows["x"], vertex_rows["y"], vertex_rows["z"]], axis=1).astype(float), faces["i"]


class SkeletonizeAgreesWithCli(unittest.TestCase):
    # Both methods on inputs that take each under a second (the default
    # method, auto, runs and measures both: 4 s on segment.ply, 30 s on the
    # tetrahedron).
    CASES = (("segment.ply", {"method": "curve"}, ("--method", "curve")),
             ("tetrahedron.off", {"method": "curve"}, ("--method", "curve")),
             ("sphere_open.ply", {"method": "curve", "repair": True}, ("--method", "curve", "--repair")))
    MEDIAL_CASES = (("tetrahedron.off", {"method": "medial", "budget": 40}, ("--method", "medial", "--budget", "40")),)

    def test_same_skeleton_as_the_command(self):
        self.check_cases(self.CASES)

    def test_same_medial_skeleton_as_the_command(self):
        self.check_cases(self.MEDIAL_CASES)

    def check_cases(self, cases):
        for name, arguments, options in cases:
            with self.subTest(mesh=name, options=options), tempfile.TemporaryDirectory() as tmp:
                path = os.path.join(DATA, "reconstruct", name)
                out = os.path.join(tmp, "skeleton.json")
                status, _, message = run_cli("skeletonize", path, "-o", out, "--quiet", *options)
                self.assertEqual(status, 0, message)
                expected = skelconv.load_skeleton_file(out)
                vertices, triangles = read_ply_or_off(path)
                got = skelconv.skeletonize(vertices, triangles, **arguments)
                self.assertGreater(len(got), 0)
                self.assertEqual(len(got), len(expected))
                self.assertEqual(got.iso, expected.iso)
                points = vertices.min(axis=0) + (vertices.max(axis=0) - vertices.min(axis=0)) * \
                    np.random.default_rng(9).random((200, 3))
                for a, b in zip(got.field(points), expected.field(points)):
                    np.testing.assert_array_equal(a, b)

    def test_errors(self):
        path = os.path.join(DATA, "reconstruct", "open_grid.obj")
        _, _, message = run_cli("skeletonize", path, "-o", os.path.join(DATA, "unused.json"), "--quiet")
        with open(path, encoding="ascii") as f:
            words = [l.split() for l in f if l.strip() and not l.startswith("#")]
        vertices = np.array([[float(x) for x in w[1:4]] for w in words if w[0] == "v"])
        faces = [[int(x) - 1 for x in w[1:]] for w in words if w[0] == "f"]
        triangles = np.array([[f[0], f[k], f[k + 1]] for f in faces for k in range(1, len(f) - 1)])
        with self.assertRaises(skelconv.InputError) as raised:
            skelconv.skeletonize(vertices, triangles)
        # The same message, the repair offered in each one's spelling.
        self.assertIn("(or pass repair=True to let skeletonize", str(raised.exception))
        self.assertEqual(path + ": " + str(raised.exception).replace("repair=True", "--repair"), message)

        path = os.path.join(DATA, "reconstruct", "segment.ply")
        vertices, triangles = read_ply_or_off(path)
        _, _, message = run_cli("skeletonize", path, "-o", os.path.join(DATA, "unused.json"), "--quiet",
                                "--prune-angle", "180")
        with self.assertRaises(skelconv.InputError) as raised:
            skelconv.skeletonize(vertices, triangles, prune_angle=180)
        self.assertEqual(str(raised.exception), "prune_angle: " + message[len("--prune-angle: "):])
        with self.assertRaises(skelconv.InputError) as raised:
            skelconv.skeletonize(vertices, triangles + len(vertices))
        self.assertTrue(str(raised.exception).startswith("triangles[0]: vertex index "), str(raised.exception))
        with self.assertRaises(skelconv.InputError) as raised:
            skelconv.skeletonize(vertices, triangles, max_triangles=10)
        self.assertIn("more than the limit 10 (--max-triangles)", str(raised.exception))


if __name__ == "__main__":
    unittest.main()
