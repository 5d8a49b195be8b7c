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
                status, out, message = run_cli("eval", path, stdin=rows_text(points))
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
                self.assertEqual(str(raised.exception), message)
                self.assertIsInstance(raised.exception, ValueError)
                # The same text parsed from a string: the message without the file name.
                with open(path, encoding="utf-8", errors="replace") as f:
                    text = f.read()
                with self.assertRaises(skelconv.InputError) as parsed:
                    skelconv.parse_skeleton_json(text)
                self.assertEqual(path + ": " + str(parsed.exception), message)

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

    def test_bad_method(self):
        skeleton = skelconv.load_skeleton_file(os.path.join(DATA, "mesh", "ring.json"))
        with self.assertRaises(skelconv.InputError) as raised:
            skeleton.mesh(iso=0.38, method="marching")
        # The CLI says "--method: marching not in {cgal,grid}".
        self.assertEqual(str(raised.exception), "method: marching not in {cgal,grid}")


if __name__ == "__main__":
    unittest.main()
