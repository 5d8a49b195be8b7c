#!/usr/bin/env python3
"""Checks `skelconv view` (docs/view.md) without a browser.

    check_view_pages.py SKELCONV BAD_FOLDER SKELETON_FOLDER... [--inject-fault]

For every skeleton of each SKELETON_FOLDER (papers_figures/skeletons, and
tests/data/view: weights, sum nodes, every family, and refusals):
  - if it holds only what the viewer shows (segments, points and SCALIS
    segments under sum nodes; the kernels of generated/glsl/), `skelconv
    view` must write a page whose skeleton data lists every primitive with
    the file's end points (a point's centre), weights and kernels, and whose fragment shader (extracted from the page) calls
    the GLSL function of every kernel and compiles with glslangValidator as
    GLSL ES 3.00 (WebGL2);
  - otherwise it must write the mesh preview: a page without fragment
    shader whose data holds a non-empty triangle mesh (base64 arrays of the
    announced sizes, indices in range, vertices on the surface's scale) and
    the reason, naming the JSON path of the first element the ray marcher
    cannot show; stdout says "mode: mesh preview" (and so for the first
    ray-marched skeleton with --mesh-preview);
  - a skeleton named no_surface_*.json (the ray marcher refuses it and the
    field stays below iso) must be refused: exit 2, one "skelconv: error:"
    line naming "iso", no file.
For every file of BAD_FOLDER (invalid skeletons, tests/data/bad) the view
must fail like `skelconv mesh` on the same file (the same message from the
same reader, exit 2) and write nothing.

--inject-fault writes a call of an undeclared function into the fragment
shader of each ray-marched page skelconv wrote, before the page is read: the
check must then fail at the compile, on every such page, and print
"CHECK-FAILED: shader does not compile: ..." (ctest view_pages_check_can_fail).
Python 3 standard library only.
"""
import json
import math
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

SHADER = re.compile(r'<script id="fragment_shader" type="x-shader/x-fragment">\n(.*?)</script>', re.S)
DATA = re.compile(r'<script id="skeleton_data" type="application/json">\n(.*?)</script>', re.S)
SUPPORTED_FAMILIES = {"inverse", "cauchy", "compact"}
POINT_DEGREE_FAMILIES = {"inverse", "cauchy", "compact"}  # the point families with a degree
# The point families of generated/glsl/point.glsl; a point of another family
# (polynomial) sends the page to the mesh preview.
POINT_GLSL_FAMILIES = {"inverse", "cauchy", "compact", "soft", "wyvill", "ferley", "gaussian"}


def kernel_name(child):
    """The GLSL function (without _f_and_grad) and the panel's kernel label."""
    kernel = child["kernel"]
    family = kernel["family"]
    if child["type"] == "point":
        label = f"point {family}" + (f" {kernel['degree']}" if family in POINT_DEGREE_FAMILIES else "")
        return f"point_{family}", label
    if child["type"] == "scalis_segment":
        return f"scalis_segment_{family}_i{kernel['degree']}", f"scalis {family} {kernel['degree']}"
    weight = child.get("weight", [1])
    degree = len(weight) - 1
    while degree > 0 and weight[degree] == 0:
        degree -= 1
    return f"segment_{family}_i{kernel['degree']}_w{degree}", f"{family} {kernel['degree']}"


def expected_terms(node, where, out):
    """The segments of a skeleton file in depth-first order with their JSON
    paths, or (path, reason) of the first element the viewer cannot show."""
    for k, child in enumerate(node):
        path = f"{where}[{k}]"
        if "blend" in child:
            if child["blend"] != "sum" or min(child.get("weights", [1])) < 0:
                return path
            bad = expected_terms(child["children"], f"{path}.children", out)
            if bad:
                return bad
            continue
        kernel = child["kernel"]
        if child.get("type") == "point":
            if kernel["family"] not in POINT_GLSL_FAMILIES or child.get("weight", 1) < 0:
                return path
            out.append((path, child))
            continue
        if child.get("type") == "scalis_segment":
            if kernel["family"] not in ("inverse", "cauchy"):
                return path
            out.append((path, child))
            continue
        if child.get("type") != "segment":
            return path
        if kernel["family"] not in SUPPORTED_FAMILIES:
            return path
        # The step bound of inverse and Cauchy terms needs w >= 0 on [0, 1]
        # (sampled here, the command solves for the least value).
        weight = child.get("weight", [1])
        least = min(sum(c * (j / 1000) ** k for k, c in enumerate(weight)) for j in range(1001))
        if kernel["family"] != "compact" and least < 0:
            return path
        out.append((path, child))
    return None


def compile_es300(shader, scratch, validator):
    source = pathlib.Path(scratch) / "page.frag"
    source.write_text(shader)
    run = subprocess.run([validator, str(source)], capture_output=True, text=True)
    return run.returncode == 0, run.stdout[-1500:] + run.stderr[-500:]


def inject_fault(page):
    """The page file with a call of an undeclared function at the end of its
    fragment shader: a page a broken `skelconv view` could have written."""
    html = page.read_text()
    match = SHADER.search(html)
    if match:
        end = match.end(1)
        html = html[:end] + "void injected_fault() { undeclared_kernel(); }\n" + html[end:]
    page.write_text(html)


def check_page(path, html, skeleton, terms, scratch, validator):
    problems = []
    shader_match, data_match = SHADER.search(html), DATA.search(html)
    if not shader_match or not data_match:
        return [f"{path}: the page has no fragment shader or no skeleton data"]
    if "http://" in html or "https://" in html:
        problems.append(f"{path}: the page refers to the network")
    data = json.loads(data_match.group(1).replace("<\\/", "</"))
    if len(data["primitives"]) != len(terms):
        problems.append(f"{path}: {len(data['primitives'])} primitives in the page, {len(terms)} in the file")
    frame = data["frame"]
    for (where, element), shown in zip(terms, data["primitives"]):
        if shown["location"] != where:
            problems.append(f"{path}: page primitive at {shown['location']}, file at {where}")
        for end in ("a", "b"):
            # The page's frame: (X - centre) / scale (view_page.hpp); a
            # point's A and B are its centre.
            expected = element["center"] if element["type"] == "point" else element[end]
            back = [shown[end][j] * frame["scale"] + frame["centre"][j] for j in range(3)]
            if max(abs(back[j] - expected[j]) for j in range(3)) > 1e-12 * max(1.0, frame["scale"]):
                problems.append(f"{path}: {where}.{end} is {back} in the page, {expected} in the file")
        function, label = kernel_name(element)
        if shown["kernel"] != label:
            problems.append(f"{path}: {where} kernel {shown['kernel']} in the page, {label} expected")
        if element["type"] == "segment":
            weight = element.get("weight", [1])
            if shown["w"][:len(weight)] != weight:
                problems.append(f"{path}: {where} weight {shown['w']} in the page, {weight} in the file")
        name = function + "_f_and_grad"
        if name + "(" not in shader_match.group(1).split("//@@", 1)[0] or not re.search(
                r"return " + name + r"\(\w+_input\(r, p\), grad\)", shader_match.group(1)):
            problems.append(f"{path}: the shader does not call {name}")
    shader = shader_match.group(1).replace("<\\/", "</")
    ok, log = compile_es300(shader, scratch, validator)
    if not ok:
        error = next((line for line in log.splitlines() if line.startswith("ERROR:")), log.strip()[:200])
        print(f"CHECK-FAILED: shader does not compile: {path}: {error}")
        problems.append(f"{path}: the page's shader does not compile as GLSL ES 3.00:\n{log}")
    return problems


def check_preview(path, html, refused_at, stdout):
    import base64
    import struct
    problems = []
    shader_match, data_match = SHADER.search(html), DATA.search(html)
    if not data_match or (shader_match and shader_match.group(1).strip()):
        return [f"{path}: the mesh preview has a fragment shader or no data"]
    data = json.loads(data_match.group(1).replace("<\\/", "</"))
    if data.get("mode") != "mesh preview" or "mode: mesh preview" not in stdout:
        problems.append(f"{path}: not announced as a mesh preview")
    if not re.search(re.escape(refused_at) + r"[:.]", data.get("reason", "")):
        problems.append(f"{path}: the reason {data.get('reason')!r} does not name {refused_at}")
    mesh = data["mesh"]
    positions = base64.b64decode(mesh["positions"])
    normals = base64.b64decode(mesh["normals"])
    indices = struct.unpack(f"<{3 * mesh['triangles']}I", base64.b64decode(mesh["indices"]))
    if mesh["triangles"] == 0 or len(positions) != 12 * mesh["vertices"] or len(normals) != len(positions):
        problems.append(f"{path}: mesh arrays of the wrong size")
    if indices and max(indices) >= mesh["vertices"]:
        problems.append(f"{path}: a triangle index out of range")
    coordinates = struct.unpack(f"<{3 * mesh['vertices']}f", positions)
    # The page's frame divides by about half the mesh's box diagonal.
    if max(abs(c) for c in coordinates) > 2.5 or abs(data["radius"] - max(
            math.sqrt(sum(coordinates[3 * k + j] ** 2 for j in range(3))) for k in range(mesh["vertices"]))) > 1e-6:
        problems.append(f"{path}: vertices out of the page's frame or radius wrong")
    return problems


def run_view(skelconv, skeleton, output):
    return subprocess.run([skelconv, "view", str(skeleton), "-o", str(output)], capture_output=True, text=True)


def check_folder(skelconv, folder, scratch, validator, fault):
    problems, shown = [], 0
    for path in sorted(pathlib.Path(folder).glob("*.json")):
        skeleton = json.loads(path.read_text())
        terms = []
        refused_at = expected_terms(skeleton["primitives"], "primitives", terms)
        output = pathlib.Path(scratch) / (path.stem + ".html")
        run = run_view(skelconv, path, output)
        if path.name.startswith("no_surface"):
            lines = run.stderr.strip().splitlines()
            if run.returncode != 2 or output.exists() or len(lines) != 1 or ": iso: no surface" not in lines[0]:
                problems.append(f"{path.name}: expected a refusal at iso (exit 2, no file), got status "
                                f"{run.returncode}, file {output.exists()}, stderr {run.stderr.strip()!r}")
            else:
                print(f"check_view_pages: {path.name}: refused: {lines[0]}")
            continue
        if refused_at is None:
            if run.returncode != 0 or not output.exists():
                problems.append(f"{path.name}: skelconv view failed (status {run.returncode}): {run.stderr.strip()}")
                continue
            shown += 1
            if fault:
                inject_fault(output)
            problems += check_page(path.name, output.read_text(), skeleton, terms, scratch, validator)
            if shown == 1:
                # --mesh-preview: the preview even where the page could ray-march.
                forced = subprocess.run([skelconv, "view", str(path), "-o", str(output), "--mesh-preview"],
                                        capture_output=True, text=True)
                if forced.returncode != 0 or "mode: mesh preview" not in forced.stdout or \
                        '"mode": "mesh preview"' not in output.read_text():
                    problems.append(f"{path.name}: --mesh-preview did not give the mesh preview: {forced.stdout!r}")
            print(f"check_view_pages: {path.name}: page of {len(terms)} primitives, {output.stat().st_size} bytes")
        else:
            if run.returncode != 0 or not output.exists():
                problems.append(f"{path.name}: expected a mesh preview (ray marcher refused at {refused_at}), got "
                                f"status {run.returncode}, stderr {run.stderr.strip()!r}")
                continue
            problems += check_preview(path.name, output.read_text(), refused_at, run.stdout)
            print(f"check_view_pages: {path.name}: mesh preview, {output.stat().st_size} bytes, "
                  + run.stdout.strip().splitlines()[-1])
    if shown == 0:
        problems.append(f"{folder}: no skeleton the viewer shows")
    return problems


def check_bad_files(skelconv, folder, scratch):
    problems = []
    count = 0
    for path in sorted(pathlib.Path(folder).glob("*.json")):
        output = pathlib.Path(scratch) / "bad.html"
        view = run_view(skelconv, path, output)
        mesh = subprocess.run([skelconv, "mesh", str(path), "-o", str(pathlib.Path(scratch) / "bad.ply"), "--quiet"],
                              capture_output=True, text=True)
        if view.returncode != 2 or output.exists() or view.stdout or view.stderr != mesh.stderr:
            problems.append(f"{path.name}: view gives status {view.returncode}, file {output.exists()}, stderr "
                            f"{view.stderr.strip()!r}; mesh gives {mesh.stderr.strip()!r}")
        count += 1
    print(f"check_view_pages: {count} bad skeleton files refused by view as by mesh")
    return problems


def main():
    arguments = [a for a in sys.argv[1:] if a != "--inject-fault"]
    fault = len(arguments) < len(sys.argv) - 1
    if len(arguments) < 3:
        sys.exit(__doc__)
    skelconv, bad, folders = arguments[0], arguments[1], arguments[2:]
    validator = shutil.which("glslangValidator")
    if not validator:
        sys.exit("check_view_pages: glslangValidator not found (Debian package glslang-tools)")
    with tempfile.TemporaryDirectory() as scratch:
        problems = []
        for folder in folders:
            problems += check_folder(skelconv, folder, scratch, validator, fault)
        problems += check_bad_files(skelconv, bad, scratch)
    for p in problems:
        print("check_view_pages: FAIL " + p, file=sys.stderr)
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
