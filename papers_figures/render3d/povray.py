"""Renders a triangle mesh with POV-Ray, headless: the mesh as a `mesh2` with
its per-vertex normals, one default camera direction (a figure may pass its
own), light and colour for every figure (the camera is framed on the mesh's
bounding sphere, or on a frame the figure gives), optionally the skeleton
drawn over it (skeleton_overlay), PNG without metadata (same mesh, same
bytes).

skelconv's frame is right-handed with z up; POV-Ray's is left-handed with y
up. Swapping y and z maps one to the other (a reflection, so the picture is
not mirrored)."""
import os
import subprocess
import tempfile

import numpy as np

# The view: from the front-right, above (skelconv coordinates, z up).
VIEW_DIRECTION = np.array([1.0, -1.6, 0.9])
CAMERA_ANGLE = 30.0                   # horizontal field of view, degrees
FRAME_MARGIN = 1.08                   # the bounding sphere fills 1/1.08 of the narrower side
SURFACE = "rgb <0.86, 0.55, 0.36>"    # one colour for every surface
# The skeleton overlay: segments as dark tubes, triangles as translucent blue plates, drawn
# through a surface made translucent so that the skeleton inside it shows.
OVERLAY_SEGMENT = "rgb <0.12, 0.12, 0.16>"
OVERLAY_TRIANGLE = "rgbf <0.15, 0.35, 0.95, 0.35>"
OVERLAY_SURFACE_FILTER = 0.0           # the surface's pigment keeps its colour...
OVERLAY_SURFACE_TRANSMIT = 0.72        # ...and lets 72 % of the light through
ANTIALIAS = "+A0.1 +AM2 +R3 -J"       # adaptive supersampling, no jitter: deterministic

SCENE = """#version 3.7;
global_settings {{ assumed_gamma 1.0 }}
background {{ rgb <1, 1, 1> }}
camera {{ perspective location {camera} look_at {centre} right x*{aspect} angle {angle} }}
light_source {{ {key} color rgb <1, 1, 1> }}
light_source {{ {fill} color rgb <0.35, 0.35, 0.4> shadowless }}
#declare Finish = finish {{ ambient 0.12 diffuse 0.75 specular 0.3 roughness 0.02 }}
#declare Surface = texture {{ pigment {{ {surface} }} finish {{ Finish }} }}
{mesh}
"""


def _pov(v):
    """skelconv (x, y, z) → POV-Ray <x, z, y>."""
    return f"<{v[0]:.9g}, {v[2]:.9g}, {v[1]:.9g}>"


def mesh2(vertices, normals, faces, colours=None):
    """The mesh as POV-Ray mesh2 text (normals estimated from the faces when
    absent). colours: optional N×3 RGB per vertex (in [0, 1]), interpolated
    over each triangle, with the finish of every other surface."""
    if normals is None:
        normals = np.zeros_like(vertices)
        tri = vertices[faces]
        face_normals = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
        for k in range(3):
            np.add.at(normals, faces[:, k], face_normals)
        normals /= np.maximum(np.linalg.norm(normals, axis=1), 1e-300)[:, None]
    parts = ["mesh2 {", f"vertex_vectors {{ {len(vertices)},"]
    parts.append(",\n".join(_pov(v) for v in vertices) + " }")
    parts.append(f"normal_vectors {{ {len(normals)},")
    parts.append(",\n".join(_pov(n) for n in normals) + " }")
    if colours is None:
        parts.append(f"face_indices {{ {len(faces)},")
        parts.append(",\n".join(f"<{a}, {b}, {c}>" for a, b, c in faces) + " }")
        parts.append("texture { Surface } }")
        return "\n".join(parts)
    parts.append(f"texture_list {{ {len(colours)},")
    parts.append(",\n".join(f"texture {{ pigment {{ rgb <{r:.4f}, {g:.4f}, {b:.4f}> }} finish {{ Finish }} }}"
                             for r, g, b in colours) + " }")
    parts.append(f"face_indices {{ {len(faces)},")
    parts.append(",\n".join(f"<{a}, {b}, {c}>, {a}, {b}, {c}" for a, b, c in faces) + " }")
    parts.append("}")
    return "\n".join(parts)


def framing(vertices):
    """(centre, radius) of the sphere the camera frames: the bounding box's
    centre and the farthest vertex from it."""
    low, high = vertices.min(axis=0), vertices.max(axis=0)
    centre = 0.5 * (low + high)
    return centre, float(np.max(np.linalg.norm(vertices - centre, axis=1)))


def scene(body, centre, radius, width, height, view=None):
    """The fixed scene (camera, lights, texture `Surface`) around `body` (POV-Ray text);
    view: the direction from the centre to the camera (skelconv coordinates), VIEW_DIRECTION
    when None."""
    half_angle = np.radians(CAMERA_ANGLE) / 2
    # the narrower field of view decides the distance
    narrow = min(half_angle, np.arctan(np.tan(half_angle) * height / width))
    distance = FRAME_MARGIN * radius / np.sin(narrow)
    direction = np.asarray(VIEW_DIRECTION if view is None else view, float)
    direction = direction / np.linalg.norm(direction)
    camera = centre + distance * direction
    key = centre + 3 * distance * np.array([0.3, -1.0, 1.6]) / np.linalg.norm([0.3, -1.0, 1.6])
    fill = centre + 3 * distance * np.array([-1.0, -0.3, 0.2]) / np.linalg.norm([-1.0, -0.3, 0.2])
    return SCENE.format(camera=_pov(camera), centre=_pov(centre), aspect=f"{width / height:.9g}",
                        angle=f"{CAMERA_ANGLE:g}", key=_pov(key), fill=_pov(fill), surface=SURFACE,
                        mesh=body)


def isosurface(function, low, high, max_gradient=10.0, accuracy=1e-4):
    """POV-Ray's own isosurface{} of `function` (POV-Ray function syntax, in
    skelconv's x, y, z) = 0, inside where it is negative, within the box
    [low, high] (skelconv coordinates): the independent cross-check of a mesh."""
    return (f"#declare SkelconvField = function(x, y, z) {{ {function} }}\n"
            f"isosurface {{ function {{ SkelconvField(x, z, y) }}\n"      # POV (x, y, z) = skelconv (x, z, y)
            f"  contained_by {{ box {{ {_pov(low)}, {_pov(high)} }} }}\n"
            f"  threshold 0 accuracy {accuracy:g} max_gradient {max_gradient:g}\n  texture {{ Surface }} }}")


def strip_png_metadata(path):
    """Rewrites the PNG keeping only the chunks that carry pixels (IHDR, PLTE,
    tRNS, gAMA, sRGB, IDAT, IEND): no text, no time."""
    keep = {b"IHDR", b"PLTE", b"tRNS", b"gAMA", b"sRGB", b"IDAT", b"IEND"}
    with open(path, "rb") as handle:
        data = handle.read()
    out, pos = [data[:8]], 8
    while pos < len(data):
        length = int.from_bytes(data[pos:pos + 4], "big")
        kind = data[pos + 4:pos + 8]
        chunk = data[pos:pos + 12 + length]
        if kind in keep:
            out.append(chunk)
        pos += 12 + length
    with open(path, "wb") as handle:
        handle.write(b"".join(out))


def skeleton_overlay(primitives, tube_radius):
    """POV-Ray text drawing a skeleton (docs/cli_skeleton.md primitives): every primitive with
    end points `a`, `b` as a tube of radius tube_radius with round ends, every primitive with
    `vertices` (triangles, polygons) as a translucent plate. Drawn with a surface made
    translucent (render(overlay=...)), so that the skeleton inside shows."""
    parts = []
    for p in primitives:
        if "a" in p and "b" in p:
            a, b = _pov(p["a"]), _pov(p["b"])
            parts.append(f"union {{ cylinder {{ {a}, {b}, {tube_radius:.9g} }} sphere {{ {a}, {tube_radius:.9g} }} "
                         f"sphere {{ {b}, {tube_radius:.9g} }} pigment {{ {OVERLAY_SEGMENT} }} finish {{ Finish }} }}")
        elif "vertices" in p:
            v = p["vertices"]
            fans = " ".join(f"triangle {{ {_pov(v[0])}, {_pov(v[k])}, {_pov(v[k + 1])} }}" for k in range(1, len(v) - 1))
            parts.append(f"mesh {{ {fans} texture {{ pigment {{ {OVERLAY_TRIANGLE} }} finish {{ Finish }} }} }}")
    return "\n".join(parts)


def render(vertices, normals, faces, png_path, width=640, height=480, povray="povray", frame=None, colours=None,
           view=None, overlay=None):
    """Renders the mesh to png_path, the camera framed on `frame` = (centre,
    radius) (default: the mesh's own bounding sphere; figures comparing
    several meshes pass one frame for all, so that their scales match),
    looking along -view (scene()). overlay: POV-Ray text (skeleton_overlay) drawn
    inside the surface, which is then translucent. Raises RuntimeError with
    POV-Ray's message on failure."""
    centre, radius = frame if frame is not None else framing(vertices)
    body = mesh2(vertices, normals, faces, colours)
    if overlay:
        see_through = (f"#declare Surface = texture {{ pigment {{ {SURFACE} filter {OVERLAY_SURFACE_FILTER:g} "
                       f"transmit {OVERLAY_SURFACE_TRANSMIT:g} }} finish {{ Finish }} }}")
        body = see_through + "\n" + overlay + "\n" + body
    render_scene(scene(body, centre, radius, width, height, view), png_path, width, height, povray)


def render_scene(text, png_path, width, height, povray="povray"):
    """Runs POV-Ray on a scene text; the PNG keeps only its pixel chunks."""
    with tempfile.TemporaryDirectory() as tmp:
        pov = os.path.join(tmp, "scene.pov")
        with open(pov, "w") as handle:
            handle.write(text)
        out = os.path.join(tmp, "out.png")
        command = [povray, f"+I{pov}", f"+O{out}", f"+W{width}", f"+H{height}", "+FN8", "-D", "-V", "-GA",
                   "+WT2"] + ANTIALIAS.split()
        run = subprocess.run(command, capture_output=True, text=True, cwd=tmp)
        if run.returncode != 0 or not os.path.exists(out):
            raise RuntimeError(f"povray failed ({run.returncode}): {run.stderr.strip()[-2000:]}")
        strip_png_metadata(out)
        _copy(out, png_path)


def _copy(src, dst):
    tmp = dst + ".tmp"
    with open(src, "rb") as a, open(tmp, "wb") as b:
        b.write(a.read())
    os.replace(tmp, dst)
