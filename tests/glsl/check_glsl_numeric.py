#!/usr/bin/python3
"""Runs the generated GLSL kernels (generated/glsl/) on points of each
region and compares f and grad f with double-precision quadrature of the
definition integral (segments and SCALIS segments) or the closed-form
definition (points).

    check_glsl_numeric.py GLSL_FOLDER [--backend chromium|cpu] [--points N]
        [--tolerance 1e-5] [--seed S] [--kernels REGEX] [--regions LIST]
        [--report-regions LIST] [--break-kernel NAME]

--kernels keeps the kernels whose function name matches REGEX (re.search).
--backend chromium runs them in headless Chromium, WebGL2 on its software
renderer SwiftShader (the GPU path: its own sqrt, exp, log, sinh); --backend
cpu compiles them as C++ in float (glsl_as_cpp.hpp; no browser: the ctest
glsl_numeric), where it also checks NAME_f beside NAME_f_and_grad.
--break-kernel NAME multiplies that kernel's results by 1 + 1e-4, a fault
the check must catch (NAME must be one of the kernels run).

A segment's SegmentInput is made by the page's segment_input() (taken from
src/view/view_march.glsl, --view-march): the compact clip [t0, t1] the
shader computes is the one checked.

Segments are drawn like the verifier's (verify/sampling.hpp): A uniform in
[-2, 2]^3, |AB| log-uniform in [0.2, 5], weights uniform in [0.2, 2], Cauchy
s log-uniform in [0.2, 5], P at a distance log-uniform in the region's
range (DISTANCES) from the segment, beside AB or beyond an end (at an angle
uniform in [0, pi/2] from the line), compact R = distance + |AB| x
log-uniform(0.3, 2) (far: distance x (1 + log-uniform(0.1, 1))). The inputs
are rounded to float first and the reference is computed on the rounded
inputs, so the error measured is the shader's evaluation alone.

Reference: f = |AB| int_0^1 w(t) K(|P - G(t)|) dt with K = (alpha r^2 +
beta)^(-n/2) (codegen/segment_families.hpp), grad f = -n alpha |AB| int w(t)
(P - G(t)) (alpha r^2 + beta)^(-(n+2)/2) dt, by composite Gauss-Legendre,
24 nodes per panel on panels graded towards the nearest point of AB
(graded_edges; compact: 64 even panels of the clipped interval).

SCALIS segments (docs/mathematics.md sec. 4): F = sigma^i |AB| int_0^1 tau(t)^(i-1)
(|P - G(t)|^2 + k sigma^2 tau(t)^2)^(-i/2) dt (k = 0 inverse, 1 Cauchy), the
generated functions' unnormalised F; A, B, P as for segments, tau0, tau1
uniform in [0.1, 1.5] |AB|, sigma 1 (inverse: the runtime's choice) or
log-uniform in [0.5, 2] (Cauchy). Points: f = w K(r) and w K'(r) (P - C)/r
(skelconv/primitives/point.hpp) in double, with r in the kernel's generic
range (inverse r log-uniform in [0.1, 10]; Cauchy s log-uniform in [0.2, 5],
r log-uniform in [0.1, 3]; supported kernels r uniform in [0.05, 0.95] R
away from Ferley's e by 0.02 R; Gaussian a r^2 uniform in [0.01, 9]).

Exit status 0 when every relative error (|f - f_ref| / |f_ref| and
|g - g_ref| / |g_ref|) in the checked regions is at most the tolerance and
every checked region compared at least one point; prints the worst per
family, degree and region, the reported regions too, and the points compared
per region. A failure prints "CHECK-FAILED: f or grad f above the tolerance
in kernels: NAME, ... (N of M points)" (every failing kernel, sorted) or
"CHECK-FAILED: no point compared in region ...".
"""
import argparse
import html
import json
import math
import os
import pathlib
import re
import subprocess
import sys
import tempfile

import numpy as np

FUNCTION = re.compile(r"^// the field and its gradient, where\n(?://[^\n]*\n)*?float (segment_(\w+?)_i(\d+)_w(\d+))_f_and_grad\(SegmentInput si, out vec3 grad\) \{\n.*?^\}\n", re.M | re.S)
SCALIS_FUNCTION = re.compile(r"^// the field and its gradient, where\n(?://[^\n]*\n)*?float (scalis_segment_(\w+?)_i(\d+))_f_and_grad\(ScalisSegmentInput si, out vec3 grad\) \{\n.*?^\}\n", re.M | re.S)
POINT_FUNCTION = re.compile(r"^float (point_(\w+?))_f\(PointInput pt\) \{\n.*?^\}\nfloat point_\w+?_f_and_grad\(PointInput pt, out vec3 grad\) \{\n.*?^\}\n", re.M | re.S)
POINT_DEGREES = {"inverse": [1, 2, 3, 4, 6, 9, 16], "cauchy": [1, 2, 3, 4, 6, 9, 16], "compact": [2, 3, 4, 6, 9, 16]}


def guarded_blocks(text):
    """The input struct and the helpers: the file's guarded blocks."""
    return "\n".join(m.group(0) for m in re.finditer(r"^#ifndef SKELCONV_\w+\n.*?^#endif\n", text, re.M | re.S))


def field_function(text, name):
    """The text of NAME_f, the field alone, or "" (then only f-and-grad runs)."""
    m = re.search(r"^float " + name + r"_f\((?:Segment|ScalisSegment)Input si\) \{\n.*?^\}\n", text, re.M | re.S)
    return m.group(0) if m else ""


# The family code of a segment in the page's primitive rows (view_march.glsl:
# texel 1's w); segment_input() clips AB to the support ball for code 1.
SEGMENT_CODE = {"inverse": 0.0, "compact": 1.0, "cauchy": 2.0}
VIEW_MARCH = pathlib.Path(__file__).resolve().parents[2] / "src" / "view" / "view_march.glsl"


def view_segment_input(path):
    """The page's Row and segment_input() (src/view/view_march.glsl), in a
    guarded block of their own: the segments' inputs, and the compact clip,
    come from the shader's code, not from this script."""
    text = pathlib.Path(path).read_text()
    row = re.search(r"^struct Row \{\n.*?^\};\n", text, re.M | re.S)
    function = re.search(r"^SegmentInput segment_input\(Row r, vec3 p\) \{\n.*?^\}\n", text, re.M | re.S)
    if not row or not function:
        sys.exit(f"check_glsl_numeric: {path}: no struct Row or no segment_input(Row r, vec3 p)")
    return ("#ifndef SKELCONV_VIEW_SEGMENT_INPUT\n#define SKELCONV_VIEW_SEGMENT_INPUT\n"
            + row.group(0) + function.group(0) + "#endif\n")


def kernels(folder, view_march):
    """(kind, family, degree, weight degree, name, source) of every kernel."""
    folder = pathlib.Path(folder)
    segment_input = view_segment_input(view_march)
    for path in sorted(folder.glob("segment_*.glsl")):
        text = path.read_text()
        for m in FUNCTION.finditer(text):
            yield ("segment", m.group(2), int(m.group(3)), int(m.group(4)), m.group(1),
                   guarded_blocks(text) + "\n" + segment_input + field_function(text, m.group(1)) + m.group(0))
    for path in sorted(folder.glob("scalis_segment_*.glsl")):
        text = path.read_text()
        for m in SCALIS_FUNCTION.finditer(text):
            yield ("scalis", m.group(2), int(m.group(3)), 0, m.group(1),
                   guarded_blocks(text) + "\n" + field_function(text, m.group(1)) + m.group(0))
    point = folder / "point.glsl"
    if point.exists():
        text = point.read_text()
        for m in POINT_FUNCTION.finditer(text):
            for degree in POINT_DEGREES.get(m.group(2), [0]):
                yield "point", m.group(2), degree, 0, m.group(1), guarded_blocks(text) + "\n" + m.group(0)


# Distance from the segment, in |AB|: beside (P projects onto AB) and beyond
# an end (its nearest point is A or B) as the verifier's generic region;
# near: either side, closer to the segment (the float loss ~ i eps |AP| / dist
# of every float form, docs/view.md); far: either side; support: compact
# only, P far from a segment whose support sphere passes 0.3-2 |AB| beyond
# it (1 - r^2/R^2 is then a difference of numbers near 1).
DISTANCES = {"beside": (0.1, 3), "beyond": (0.1, 3), "near": (1e-3, 0.1), "far": (3, 100), "support": (3, 100)}
REGIONS = ("beside", "beyond", "far", "near", "support")
REGION_TITLE = {"beside": "beside AB", "beyond": "beyond an end", "far": "far", "near": "near AB", "support": "support edge"}
# Relative errors are measured where the reference f and |grad f| lie in
# [1e-25, 1e25]: outside it the float result underflows or overflows
# somewhere on its way (float's normal range is 1.2e-38 to 3.4e38, and
# q^(-n/2-1) is far smaller than f far from a high-degree kernel); those
# points are counted and left out.
FLOAT_RANGE = (1e-25, 1e25)


def unit(v):
    return v / np.linalg.norm(v)


def draw(rng, family, count, region="beside"):
    """count rows a, b, p, w, s, R in `region` (REGIONS), then a flag: 1 where
    P is beyond an end (its nearest point is A or B), 0 where it projects onto
    AB."""
    rows = []
    for _ in range(count):
        a = rng.uniform(-2, 2, 3)
        length = math.exp(rng.uniform(math.log(0.2), math.log(5)))
        d = unit(rng.normal(size=3))
        b = a + length * d
        w = rng.uniform(0.2, 2, 4)
        s = math.exp(rng.uniform(math.log(0.2), math.log(5)))
        low, high = DISTANCES[region]
        dist = length * math.exp(rng.uniform(math.log(low), math.log(high)))
        tau = rng.uniform(0, 1)
        if region == "beyond" or (region in ("far", "near", "support") and rng.uniform() < 0.5):
            tau = -1 if rng.uniform() < 0.5 else 2
        perp = unit(np.cross(d, rng.normal(size=3)))
        if 0 <= tau <= 1:
            p = a + tau * length * d + dist * perp
        else:
            # At angle theta from the line, outwards from the nearer end.
            theta = rng.uniform(0, math.pi / 2)
            out = -1 if tau < 0 else 1
            p = (a if tau < 0 else b) + dist * (math.sin(theta) * perp + out * math.cos(theta) * d)
        # Compact: the support sphere reaches 0.3-2 |AB| past the segment's
        # nearest point, or in the far region 0.1-1 times the distance (at
        # 100 |AB| a margin of |AB| is the support region's grazing case).
        margin = dist * log_uniform(rng, 0.1, 1) if region == "far" else length * log_uniform(rng, 0.3, 2)
        row = np.concatenate([a, b, p, w, [s, dist + margin]]).astype(np.float32).astype(np.float64)
        t = (row[6:9] - row[0:3]) @ (row[3:6] - row[0:3]) / ((row[3:6] - row[0:3]) @ (row[3:6] - row[0:3]))
        row = np.append(row, 0.0 if 0 <= t <= 1 else 1.0)
        rows.append(row)
    return rows


def log_uniform(rng, low, high):
    return math.exp(rng.uniform(math.log(low), math.log(high)))


def draw_scalis(rng, family, count, region="beside"):
    """Rows a, b, p, tau0, tau1, sigma (and the side flag), as draw()."""
    rows = []
    for row in draw(rng, "inverse", count, region):
        length = np.linalg.norm(row[3:6] - row[0:3])
        tau = rng.uniform(0.1, 1.5, 2) * length
        sigma = 1.0 if family == "inverse" else log_uniform(rng, 0.5, 2)
        out = np.concatenate([row[0:9], tau, [sigma]]).astype(np.float32).astype(np.float64)
        rows.append(np.append(out, row[15]))
    return rows


def point_radius(rng, family, R, e, a):
    if family == "inverse":
        return log_uniform(rng, 0.1, 10)
    if family == "cauchy":
        return log_uniform(rng, 0.1, 3)
    if family == "gaussian":
        return math.sqrt(rng.uniform(0.01, 9) / a)
    while True:
        r = rng.uniform(0.05, 0.95) * R
        if family != "ferley" or abs(r - e) > 0.02 * R:
            return r


def draw_point(rng, family, degree, count):
    """Rows c, p, w, i, s, R, e, a, b (and a side flag of 0)."""
    rows = []
    for _ in range(count):
        c = rng.uniform(-2, 2, 3)
        R = log_uniform(rng, 0.3, 3)
        e = rng.uniform(0.2, 0.8) * R
        a, b = log_uniform(rng, 0.2, 5), rng.uniform(0.5, 2)
        s = log_uniform(rng, 0.2, 5)
        r = point_radius(rng, family, R, e, a)
        p = c + r * unit(rng.normal(size=3))
        row = np.concatenate([c, p, [rng.uniform(0.2, 2), degree, s, R, e, a, b]]).astype(np.float32).astype(np.float64)
        rows.append(np.append(row, 0.0))
    return rows


def point_reference(family, degree, row):
    """w K(r) and w K'(r) (P - C)/r: the traits of include/skelconv/kernels/."""
    c, p, w, i, s, R, e, a, b = row[0:3], row[3:6], row[6], row[7], row[8], row[9], row[10], row[11], row[12]
    d = p - c
    r = float(np.linalg.norm(d))
    v = 1 - r * r / (R * R)
    if family == "inverse":
        K, dK = r ** -i, -i * r ** (-i - 1)
    elif family == "cauchy":
        K, dK = (1 + s * r * r) ** (-i / 2), -i * s * r * (1 + s * r * r) ** (-i / 2 - 1)
    elif family == "compact":
        K, dK = v ** (i / 2), -i * r / (R * R) * v ** (i / 2 - 1)
    elif family == "soft":
        K, dK = v * v, -4 * r / (R * R) * v
    elif family == "wyvill":
        K, dK = v * v * (5 + 4 * v) / 9, -v * (10 + 12 * v) / 9 * 2 * r / (R * R)
    elif family == "ferley":
        k = 2 / (R - e)
        K, dK = (1 + k * (e - r), -k) if r < e else ((r - R) ** 2 / (e - R) ** 2, 2 * (r - R) / (e - R) ** 2)
    else:
        K, dK = b * math.exp(-a * r * r), -2 * a * b * r * math.exp(-a * r * r)
    return w * K, w * dK * d / r


def graded_edges(a, b, p, lo=0.0, hi=1.0):
    """Panel ends on [lo, hi] graded towards c, the parameter of the point of
    AB nearest to P: c +- h (2^k - 1), h = that distance / |AB| (at least
    2^-40), each panel then cut in 4. A panel at distance x from c is about
    x wide and the integrand's complex singularities (at imaginary distance
    >= h from c) are about x away from it, so 24 Gauss-Legendre nodes per
    piece integrate it to double rounding, whatever h."""
    ab = b - a
    c = min(hi, max(lo, float((p - a) @ ab / (ab @ ab))))
    h = max(float(np.linalg.norm(p - (a + c * ab))) / float(np.linalg.norm(ab)), 2.0 ** -40)
    ends = {lo, hi, c}
    for sign in (-1, 1):
        k = 1
        while True:
            x = c + sign * h * (2.0 ** k - 1)
            if not (lo < x < hi):
                break
            ends.add(x)
            k += 1
    coarse = sorted(ends)
    return np.array(sorted({u + (v - u) * j / 4 for u, v in zip(coarse, coarse[1:]) for j in range(4)} | {hi}))


def scalis_reference(family, degree, row):
    a, b, p, tau0, tau1, sigma = row[0:3], row[3:6], row[6:9], row[9], row[10], row[11]
    edges = graded_edges(a, b, p)
    t = ((edges[:-1, None] + edges[1:, None]) / 2 + (edges[1:, None] - edges[:-1, None]) / 2 * NODES[None, :]).ravel()
    wq = ((edges[1:, None] - edges[:-1, None]) / 2 * WEIGHTS[None, :]).ravel()
    tau = tau0 + (tau1 - tau0) * t
    diff = p[None, :] - (a[None, :] + t[:, None] * (b - a)[None, :])
    q = np.einsum("ij,ij->i", diff, diff) + (sigma * tau) ** 2 * (family == "cauchy")
    length = np.linalg.norm(b - a)
    v = sigma ** degree * length * wq * tau ** (degree - 1)
    f = np.sum(v * q ** (-degree / 2))
    g = -degree * np.sum((v * q ** (-degree / 2 - 1))[:, None] * diff, axis=0)
    return f, g


def clip(a, b, p, R):
    """[t0, t1]: the part of AB inside the ball of radius R around p."""
    ab, ap = b - a, p - a
    qa, qb, qc = ab @ ab, ab @ ap, ap @ ap - R * R
    disc = qb * qb - qa * qc
    if disc <= 0:
        return None
    root = math.sqrt(disc)
    t0, t1 = max(0.0, (qb - root) / qa), min(1.0, (qb + root) / qa)
    return (t0, t1) if t0 < t1 else None


NODES, WEIGHTS = np.polynomial.legendre.leggauss(24)


def reference(family, degree, wdeg, row):
    a, b, p, w, s, R = row[0:3], row[3:6], row[6:9], row[9:13], row[13], row[14]
    alpha, beta, n = {"inverse": (1.0, 0.0, degree), "cauchy": (s, 1.0, degree), "compact": (-1 / (R * R), 1.0, -degree)}[family]
    lo, hi = 0.0, 1.0
    if family == "compact":
        c = clip(a, b, p, R)
        if c is None:
            return 0.0, np.zeros(3)
        lo, hi = c
    edges = np.linspace(lo, hi, 65) if family == "compact" else graded_edges(a, b, p)
    t = ((edges[:-1, None] + edges[1:, None]) / 2 + (edges[1:, None] - edges[:-1, None]) / 2 * NODES[None, :]).ravel()
    wq = ((edges[1:, None] - edges[:-1, None]) / 2 * WEIGHTS[None, :]).ravel()
    weight = sum(w[k] * t**k for k in range(wdeg + 1))
    diff = p[None, :] - (a[None, :] + t[:, None] * (b - a)[None, :])
    q = alpha * np.einsum("ij,ij->i", diff, diff) + beta
    length = np.linalg.norm(b - a)
    f = length * np.sum(wq * weight * q ** (-n / 2))
    g = -n * alpha * length * np.sum((wq * weight * q ** (-(n + 2) / 2))[:, None] * diff, axis=0)
    return f, g


# The input of each kind from the texels t0 .. t4 (20 floats per row). A
# segment's row is A, B, P, w, s, R and the page's family code
# (SEGMENT_CODE); its SegmentInput, with the compact clip [t0, t1], is made
# by the page's own segment_input() (view_segment_input()).
SETUP = {
    "segment": "Row r = Row(vec4(t0.xyz, 0.0), vec4(t0.w, t1.xy, t3.w), vec4(t2.yzw, t3.x), vec4(t3.y, t3.z, 1.0, 0.0)); "
               "SegmentInput si = segment_input(r, vec3(t1.zw, t2.x));",
    "scalis": "ScalisSegmentInput si = ScalisSegmentInput(t0.xyz, vec3(t0.w, t1.xy), vec3(t1.zw, t2.x), t2.y, t2.z, t2.w);",
    "point": "PointInput si = PointInput(t0.xyz, vec3(t0.w, t1.xy), t1.z, t1.w, t2.x, t2.y, t2.z, t2.w, t3.x);",
}

PAGE = """<!doctype html><html><body><pre id="out">running</pre><script>
const jobs = %s;
const results = {};
const gl = document.createElement('canvas').getContext('webgl2');
const out = document.getElementById('out');
try {
  if (!gl) throw new Error('no WebGL2');
  if (!gl.getExtension('EXT_color_buffer_float')) throw new Error('no EXT_color_buffer_float');
  const vs = `#version 300 es
  void main() { vec2 c[3] = vec2[3](vec2(-1,-1), vec2(3,-1), vec2(-1,3)); gl_Position = vec4(c[gl_VertexID], 0, 1); }`;
  function shader(type, src) {
    const s = gl.createShader(type); gl.shaderSource(s, src); gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(s));
    return s;
  }
  const vshader = shader(gl.VERTEX_SHADER, vs);
  for (const job of jobs) {
    const fs = `#version 300 es
precision highp float;
precision highp sampler2D;
${job.source}
uniform sampler2D inputs;
out vec4 colour;
void main() {
  int i = int(gl_FragCoord.x);
  vec4 t0 = texelFetch(inputs, ivec2(0, i), 0), t1 = texelFetch(inputs, ivec2(1, i), 0),
       t2 = texelFetch(inputs, ivec2(2, i), 0), t3 = texelFetch(inputs, ivec2(3, i), 0),
       t4 = texelFetch(inputs, ivec2(4, i), 0);
  ${job.setup}
  vec3 grad;
  float f = ${job.name}_f_and_grad(si, grad);
  colour = vec4(f, grad);
}`;
    const prog = gl.createProgram();
    gl.attachShader(prog, vshader); gl.attachShader(prog, shader(gl.FRAGMENT_SHADER, fs));
    gl.linkProgram(prog);
    if (!gl.getProgramParameter(prog, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(prog));
    const n = job.inputs.length / 20;
    const tex = gl.createTexture(); gl.bindTexture(gl.TEXTURE_2D, tex);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, 5, n, 0, gl.RGBA, gl.FLOAT, new Float32Array(job.inputs));
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    const target = gl.createTexture(); gl.bindTexture(gl.TEXTURE_2D, target);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, n, 1, 0, gl.RGBA, gl.FLOAT, null);
    const fb = gl.createFramebuffer(); gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, target, 0);
    gl.viewport(0, 0, n, 1); gl.useProgram(prog);
    gl.activeTexture(gl.TEXTURE0); gl.bindTexture(gl.TEXTURE_2D, tex);
    gl.uniform1i(gl.getUniformLocation(prog, 'inputs'), 0);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    const pixels = new Float32Array(4 * n);
    gl.readPixels(0, 0, n, 1, gl.RGBA, gl.FLOAT, pixels);
    results[job.key] = Array.from(pixels);
  }
  out.textContent = 'RESULTS ' + JSON.stringify(results) + ' END';
} catch (e) {
  out.textContent = 'ERROR ' + e.message + ' END';
}
</script></body></html>
"""

CHROMIUM_FLAGS = ["--headless=new", "--use-gl=angle", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                  "--no-sandbox", "--disable-gpu-sandbox", "--disable-background-networking",
                  "--disable-component-update", "--disable-sync", "--no-first-run", "--virtual-time-budget=600000"]


# The inputs of each kind from the 20 floats of a row (`in`), for the cpu
# backend (the same fields as SETUP).
CPU_SETUP = {
    "segment": "Row r{vec4(in[0], in[1], in[2], 0.0f), vec4(in[3], in[4], in[5], in[15]), "
               "vec4(in[9], in[10], in[11], in[12]), vec4(in[13], in[14], 1.0f, 0.0f)}; "
               "SegmentInput si = segment_input(r, vec3(in[6], in[7], in[8]));",
    "scalis": "ScalisSegmentInput si{vec3(in[0], in[1], in[2]), vec3(in[3], in[4], in[5]), vec3(in[6], in[7], in[8]), "
              "in[9], in[10], in[11]};",
    "point": "PointInput si{vec3(in[0], in[1], in[2]), vec3(in[3], in[4], in[5]), in[6], in[7], in[8], in[9], in[10], "
             "in[11], in[12]};",
}

# GLSL to C++: `out`/`inout` parameters become references; float[N](...)
# array initialisers braced lists; a literal with a point or an exponent is
# a float in GLSL, a double in C++ (the suffix f keeps the arithmetic in
# float).
OUT_PARAMETER = re.compile(r"\b(?:out|inout) (float|vec3) (\w+)")
# The swizzles of segment_input()'s row texels (r.t0 .. r.t3): .xyz a method
# of glsl_as_cpp.hpp's vec4, one component an index.
ROW_SWIZZLE = re.compile(r"\b(r\.t[0-3])\.(xyz|[xyzw])\b")
ARRAY_INITIALISER = re.compile(r"float\[\d+\]\(([^;]*)\);", re.S)
FLOAT_LITERAL = re.compile(r"(?<![\w.])(\d+\.\d*(?:[eE][+-]?\d+)?|\d+[eE][+-]?\d+)(?![\w.])")


def glsl_to_cpp(source):
    out = []
    for line in source.splitlines():
        code, sep, comment = line.partition("//")
        code = OUT_PARAMETER.sub(r"\1& \2", code)
        code = ROW_SWIZZLE.sub(lambda m: m.group(1) + (".xyz()" if m.group(2) == "xyz" else f"[{'xyzw'.index(m.group(2))}]"),
                               code)
        out.append(FLOAT_LITERAL.sub(r"\1f", code) + sep + comment)
    return ARRAY_INITIALISER.sub(r"{\1};", "\n".join(out) + "\n")


def run_cpu(jobs, compiler, scratch):
    """Every job's f and f-and-grad, compiled as C++ in float (glsl_as_cpp.hpp):
    values [f, g0, g1, g2, f of the _f function] per row."""
    sources, seen = [], set()
    for job in jobs:
        if job["name"] not in seen:
            seen.add(job["name"])
            sources.append(glsl_to_cpp(job["source"]))
    runners = []
    for k, job in enumerate(jobs):
        runners.append(f"void run{k}(const float* in, float* out) {{\n  {CPU_SETUP[job['kind']]}\n  vec3 grad;\n"
                       f"  out[0] = {job['name']}_f_and_grad(si, grad);\n"
                       f"  out[1] = grad[0]; out[2] = grad[1]; out[3] = grad[2];\n"
                       f"  out[4] = {job['name']}_f(si);\n}}\n")
    table = ", ".join(f"run{k}" for k in range(len(jobs)))
    here = pathlib.Path(__file__).resolve().parent
    program = (f'#include "{here / "glsl_as_cpp.hpp"}"\n#include <cstdio>\n#include <vector>\n'
               + "\n".join(sources) + "\n".join(runners)
               + "using Runner = void (*)(const float*, float*);\n"
               + f"static const Runner runners[] = {{{table}}};\n"
               + "int main() {\n  int job, rows;\n"
               + "  while (std::fread(&job, 4, 1, stdin) == 1 && std::fread(&rows, 4, 1, stdin) == 1) {\n"
               + "    std::vector<float> in(20 * rows), out(5 * rows);\n"
               + "    if (std::fread(in.data(), 4, in.size(), stdin) != in.size()) return 3;\n"
               + "    for (int r = 0; r < rows; ++r) runners[job](&in[20 * r], &out[5 * r]);\n"
               + "    std::fwrite(out.data(), 4, out.size(), stdout);\n  }\n  return 0;\n}\n")
    cpp, exe = pathlib.Path(scratch) / "glsl_as_cpp.cpp", pathlib.Path(scratch) / "glsl_as_cpp"
    cpp.write_text(program)
    build = subprocess.run([compiler, "-std=c++20", "-O1", "-ffp-contract=off", "-w", str(cpp), "-o", str(exe)],
                           capture_output=True, text=True)
    if build.returncode != 0:
        sys.exit("check_glsl_numeric: the GLSL does not compile as C++:\n" + build.stderr[-3000:])
    stdin = b"".join(np.array([k, len(job["inputs"]) // 20], dtype=np.int32).tobytes()
                     + np.array(job["inputs"], dtype=np.float32).tobytes() for k, job in enumerate(jobs))
    run = subprocess.run([str(exe)], input=stdin, capture_output=True)
    if run.returncode != 0:
        sys.exit(f"check_glsl_numeric: the compiled kernels failed (status {run.returncode})")
    values = np.frombuffer(run.stdout, dtype=np.float32).astype(np.float64)
    results, at = {}, 0
    for job in jobs:
        n = 5 * (len(job["inputs"]) // 20)
        results[job["key"]] = list(values[at:at + n])
        at += n
    return results


def run_chromium(jobs, chromium, scratch):
    """Every job's f and grad from f-and-grad in WebGL2: [f, g0, g1, g2] per row."""
    page = pathlib.Path(scratch) / "glsl_numeric.html"
    page.write_text(PAGE % json.dumps(jobs))
    profile = pathlib.Path(scratch) / "profile"
    run = subprocess.run([chromium, *CHROMIUM_FLAGS, f"--user-data-dir={profile}", "--dump-dom",
                          page.as_uri()], capture_output=True, text=True, timeout=1800)
    m = re.search(r'<pre id="out">(RESULTS|ERROR) (.*?) END</pre>', run.stdout, re.S)
    if not m:
        sys.exit("check_glsl_numeric: no result in the page (chromium stderr tail):\n" + run.stderr[-2000:])
    if m.group(1) == "ERROR":
        sys.exit("check_glsl_numeric: the page failed: " + m.group(2))
    return {key: [math.nan if v is None else v for v in values]  # JSON null: NaN
            for key, values in json.loads(html.unescape(m.group(2))).items()}




def make_jobs(args):
    """The kernels' jobs (inputs) and their references, per region."""
    rng = np.random.default_rng(args.seed)
    jobs, refs = [], {}
    for kind, family, degree, wdeg, name, source in kernels(args.folder, args.view_march):
        if not re.search(args.kernels, name):
            continue
        regions = args.regions + args.report_regions
        for region in (["point"] if kind == "point" else
                       [r for r in regions if r != "support" or (kind == "segment" and family == "compact")]):
            flat, expected = [], []
            if kind == "segment":
                for row in draw(rng, family, args.points, region):
                    f, g = reference(family, degree, wdeg, row)
                    flat += list(row[:15]) + [SEGMENT_CODE[family], 0.0, 0.0, 0.0, 0.0]
                    expected.append((f, g))
            else:
                rows = (draw_scalis(rng, family, args.points, region) if kind == "scalis"
                        else draw_point(rng, family, degree, args.points))
                for row in rows:
                    expected.append(scalis_reference(family, degree, row) if kind == "scalis"
                                    else point_reference(family, degree, row))
                    flat += list(row[:-1]) + [0.0] * (21 - len(row))
            key = f"{name}@{degree}@{region}"
            jobs.append({"name": name, "key": key, "kind": kind, "source": source, "setup": SETUP[kind],
                         "inputs": flat})
            refs[key] = (kind + " " + family, degree, region, expected)
    return jobs, refs


def relative_error(got, want):
    scale = np.linalg.norm(want)
    return float(np.linalg.norm(np.array(got) - want) / scale if scale != 0 else np.linalg.norm(got))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("folder")
    ap.add_argument("--points", type=int, default=32, help="points per kernel and region")
    ap.add_argument("--tolerance", type=float, default=1e-5)
    ap.add_argument("--seed", type=int, default=20261204)
    ap.add_argument("--backend", choices=("chromium", "cpu"), default="chromium")
    ap.add_argument("--chromium", default="/usr/bin/chromium")
    ap.add_argument("--compiler", default="c++", help="C++ compiler of the cpu backend")
    ap.add_argument("--view-march", default=str(VIEW_MARCH), help="the page's shader, for its segment_input()")
    ap.add_argument("--kernels", default="", help="only the kernels whose name matches this regular expression")
    ap.add_argument("--regions", default="beside,beyond,far",
                    help="segments: the regions checked against the tolerance, a comma-separated subset of " + ",".join(REGIONS))
    ap.add_argument("--report-regions", default="", help="regions measured and printed, not checked")
    ap.add_argument("--break-kernel", default="", help="a fault for the check to catch: this kernel's f and grad x (1 + 1e-4)")
    args = ap.parse_args()
    args.regions = [r for r in args.regions.split(",") if r]
    args.report_regions = [r for r in args.report_regions.split(",") if r]
    for r in args.regions + args.report_regions:
        if r not in REGIONS:
            sys.exit(f"check_glsl_numeric: unknown region {r!r} (one of {', '.join(REGIONS)})")
    if args.backend == "chromium" and not os.path.exists(args.chromium):
        sys.exit(f"check_glsl_numeric: {args.chromium} not found (Debian package chromium)")
    jobs, refs = make_jobs(args)
    if not jobs:
        sys.exit(f"check_glsl_numeric: no kernel of {args.folder} matches {args.kernels!r}")
    if args.break_kernel:
        broken = [j for j in jobs if j["name"] == args.break_kernel]
        if not broken:
            sys.exit(f"check_glsl_numeric: --break-kernel {args.break_kernel}: no such kernel")
        for job in broken:  # the kernel's own functions, after the guarded blocks
            blocks, _, functions = job["source"].rpartition("#endif\n")
            job["source"] = blocks + "#endif\n" + re.sub(r"^(\s*)return (.*);$", r"\1return (1.0 + 1e-4) * (\2);",
                                                         functions, flags=re.M)
    with tempfile.TemporaryDirectory() as scratch:
        results = (run_cpu(jobs, args.compiler, scratch) if args.backend == "cpu"
                   else run_chromium(jobs, args.chromium, scratch))
    worst, per_degree, out_of_range = {}, {}, {}
    compared = {}   # region: points compared against the tolerance
    failing = {}    # kernel name: points above the tolerance
    width = 5 if args.backend == "cpu" else 4
    for key, (family, degree, region, expected) in refs.items():
        checked = region not in args.report_regions
        if checked:
            compared.setdefault(region, 0)
        values = results.get(key)
        if values is None or len(values) < width * len(expected):
            failing[key.split("@")[0]] = failing.get(key.split("@")[0], 0) + len(expected)
            print(f"check_glsl_numeric: {key}: no result from the {args.backend} backend")
            continue
        for k, (f, g) in enumerate(expected):
            if not all(FLOAT_RANGE[0] <= v <= FLOAT_RANGE[1] for v in (abs(f), np.linalg.norm(g)) if v != 0):
                out_of_range[region] = out_of_range.get(region, 0) + 1
                continue
            got = values[width * k:width * k + width]
            ef = relative_error([got[0]], [f])
            if width == 5:
                ef = max(ef, relative_error([got[4]], [f]))
            eg = relative_error(got[1:4], g)
            ef, eg = (math.inf if e != e else e for e in (ef, eg))  # NaN: fails
            if checked:
                compared[region] += 1
                if not (ef <= args.tolerance and eg <= args.tolerance):
                    name = key.split("@")[0]
                    failing[name] = failing.get(name, 0) + 1
            d = per_degree.setdefault((family, degree, region), [0.0, 0.0])
            d[0], d[1] = max(d[0], ef), max(d[1], eg)
            w = worst.setdefault((family, checked), [0.0, "", 0.0, ""])
            if ef > w[0]:
                w[0], w[1] = ef, key
            if eg > w[2]:
                w[2], w[3] = eg, key
    print(f"check_glsl_numeric ({args.backend}): {len(results)} kernel-regions x {args.points} points, "
          f"checked: {', '.join(args.regions) or 'points only'}; reported: {', '.join(args.report_regions) or '-'}; "
          f"tolerance {args.tolerance:g}")
    for (family, checked), (ef, nf, eg, ng) in sorted(worst.items()):
        what = "" if checked else " (reported regions)"
        print(f"  {family:16s} worst f rel. error {ef:.2e} ({nf}), worst grad {eg:.2e} ({ng}){what}")
    print("  worst per family, degree and region (f / grad; every weight degree):")
    for (family, degree, region), (ef, eg) in sorted(per_degree.items()):
        mark = "" if ef <= args.tolerance and eg <= args.tolerance else "  above"
        if region in args.report_regions:
            mark += "  (reported)" if mark else ""
        print(f"    {family:16s} i={degree:2d} {REGION_TITLE.get(region, region):14s} {ef:.1e} / {eg:.1e}{mark}")
    for region, n in sorted(out_of_range.items()):
        print(f"  {region}: {n} points left out, the reference outside [{FLOAT_RANGE[0]:g}, {FLOAT_RANGE[1]:g}]")
    # A check that compared nothing proves nothing: every checked region of
    # the selected kernels must have compared points.
    print("  points compared per checked region: "
          + ", ".join(f"{REGION_TITLE.get(r, r)} {n}" for r, n in sorted(compared.items())))
    empty = [r for r, n in sorted(compared.items()) if n == 0]
    if empty or not compared:
        print(f"CHECK-FAILED: no point compared in region {', '.join(empty) or '(none checked)'}")
    if failing:
        print(f"CHECK-FAILED: f or grad f above the tolerance in kernels: {', '.join(sorted(failing))} "
              f"({sum(failing.values())} of {sum(compared.values())} points)")
    return 1 if failing or empty or not compared else 0

if __name__ == "__main__":
    sys.exit(main())
