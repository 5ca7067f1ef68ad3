#!/usr/bin/env python3
"""Regenerates the figures of the user manual and README from the tool's output.

    python3 doc/Polygon_mesh_processing_ILSA/make_figures.py [BUILD_DIR] [--check]

BUILD_DIR (default: build) holds the built `ilsa_smooth`. For each mesh the
tool writes the input and the smoothed mesh with faces coloured by aspect ratio
q (`--iterations 0 --color-by-quality`, then the defaults with
`--color-by-quality`); this script renders both side by side (its own small
z-buffer rasteriser, flat shading, no dependency beyond Python 3), draws the
histogram of q before and after as SVG, and writes everything to the `fig`
directory next to it. Nothing here is random: rerunning it gives the same files.
With --check it writes nothing there and fails unless the figures it makes are
the ones in `fig` (same pixels, same SVG): the test suite runs it so.
"""

import math
import os
import struct
import subprocess
import sys
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
FIG = os.path.join(HERE, "fig")
MESHES = os.path.join(ROOT, "data", "meshes")

# name, file, yaw, pitch and roll of the view (degrees), image width of one panel, edges drawn
FIGURES = [
    ("horse", "horse.ply", -90.0, 0.0, -90.0, 560, False),
    ("fandisk", "fandisk.off", 150.0, 30.0, 0.0, 640, True),
    ("shark", "mech-holes-shark.off", 30.0, 35.0, 0.0, 640, True),
]


def run_tool(tool, mesh, output, *flags):
    command = [tool, mesh, output, "--color-by-quality", "--no-progress", "--report", "summary", *flags]
    result = subprocess.run(command, capture_output=True, text=True, check=True)
    return result.stdout


def read_ply(path):
    """Vertices (x, y, z) and faces ((i, j, k), (r, g, b)) of a binary little-endian PLY."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    if "format binary_little_endian 1.0" not in header:
        raise ValueError(path + ": expected a binary little-endian PLY")
    sizes = {"char": "b", "uchar": "B", "short": "h", "ushort": "H", "int": "i", "uint": "I",
             "float": "f", "double": "d"}
    elements, current = [], None
    for line in header:
        words = line.split()
        if words[0] == "element":
            current = (words[1], int(words[2]), [])
            elements.append(current)
        elif words[0] == "property":
            current[2].append(words[1:])
    offset, vertices, faces = end, [], []
    for name, count, properties in elements:
        for _ in range(count):
            values = {}
            for p in properties:
                if p[0] == "list":
                    n = struct.unpack_from("<" + sizes[p[1]], data, offset)[0]
                    offset += struct.calcsize(sizes[p[1]])
                    fmt = "<%d%s" % (n, sizes[p[2]])
                    values[p[3]] = struct.unpack_from(fmt, data, offset)
                    offset += struct.calcsize(fmt)
                else:
                    fmt = "<" + sizes[p[0]]
                    values[p[1]] = struct.unpack_from(fmt, data, offset)[0]
                    offset += struct.calcsize(fmt)
            if name == "vertex":
                vertices.append((values["x"], values["y"], values["z"]))
            elif name == "face":
                faces.append((values["vertex_indices"], (values["red"], values["green"], values["blue"])))
    return vertices, faces


def aspect_ratio(a, b, c):
    """q = 2√3·r_in/l_max, as the package computes it."""
    def sub(p, q):
        return (p[0] - q[0], p[1] - q[1], p[2] - q[2])
    def norm(v):
        return math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
    u, v = sub(b, a), sub(c, a)
    n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    lengths = (norm(sub(c, b)), norm(sub(a, c)), norm(sub(b, a)))
    longest = max(lengths)
    return 2 * math.sqrt(3) * norm(n) / (sum(lengths) * longest) if longest > 0 else 0.0


def render(vertices, faces, yaw, pitch, roll, width, edges, box):
    """RGB rows of the mesh seen from (yaw, pitch, roll), orthographic, fitted to `box`."""
    cy, sy = math.cos(math.radians(yaw)), math.sin(math.radians(yaw))
    cp, sp = math.cos(math.radians(pitch)), math.sin(math.radians(pitch))
    cr, sr = math.cos(math.radians(roll)), math.sin(math.radians(roll))
    def view(p):
        x, y, z = p[0] - box[0][0], p[1] - box[0][1], p[2] - box[0][2]
        x, z = cy * x + sy * z, -sy * x + cy * z   # about the vertical (y) axis
        y, z = cp * y - sp * z, sp * y + cp * z    # then about the horizontal axis
        x, y = cr * x - sr * y, sr * x + cr * y    # then in the image plane
        return (x, y, z)
    projected = [view(p) for p in vertices]
    xs, ys = [p[0] for p in projected], [p[1] for p in projected]
    margin = 0.04
    scale = (1 - 2 * margin) * width / max(max(xs) - min(xs), 1e-300)
    height = int(math.ceil((max(ys) - min(ys)) * scale / (1 - 2 * margin)))
    ox, oy = min(xs) - margin * width / scale, max(ys) + margin * height / scale
    screen = [((p[0] - ox) * scale, (oy - p[1]) * scale, p[2]) for p in projected]
    depth = [-math.inf] * (width * height)
    pixels = [(255, 255, 255)] * (width * height)
    light = (0.3, 0.4, 0.87)
    for (i, j, k), color in faces:
        a, b, c = screen[i], screen[j], screen[k]
        area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
        if area == 0:
            continue
        pa, pb, pc = projected[i], projected[j], projected[k]
        u = (pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2])
        v = (pc[0] - pa[0], pc[1] - pa[1], pc[2] - pa[2])
        n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        length = math.sqrt(n[0] ** 2 + n[1] ** 2 + n[2] ** 2) or 1.0
        shade = 0.55 + 0.45 * abs(n[0] * light[0] + n[1] * light[1] + n[2] * light[2]) / length
        x0, x1 = max(int(min(a[0], b[0], c[0])), 0), min(int(max(a[0], b[0], c[0])) + 1, width - 1)
        y0, y1 = max(int(min(a[1], b[1], c[1])), 0), min(int(max(a[1], b[1], c[1])) + 1, height - 1)
        # Distances to the edges in pixels, for the wireframe.
        lengths = [math.hypot(q[0] - p[0], q[1] - p[1]) or 1.0 for p, q in ((b, c), (c, a), (a, b))]
        for y in range(y0, y1 + 1):
            py = y + 0.5
            for x in range(x0, x1 + 1):
                px = x + 0.5
                w0 = ((c[0] - b[0]) * (py - b[1]) - (c[1] - b[1]) * (px - b[0])) / area
                w1 = ((a[0] - c[0]) * (py - c[1]) - (a[1] - c[1]) * (px - c[0])) / area
                w2 = 1 - w0 - w1
                if w0 < 0 or w1 < 0 or w2 < 0:
                    continue
                z = w0 * a[2] + w1 * b[2] + w2 * c[2]
                at = y * width + x
                if z <= depth[at]:
                    continue
                depth[at] = z
                s = shade
                if edges and min(w0 * abs(area) / lengths[0], w1 * abs(area) / lengths[1],
                                 w2 * abs(area) / lengths[2]) < 0.3:
                    s *= 0.7
                pixels[at] = (int(color[0] * s), int(color[1] * s), int(color[2] * s))
    return [pixels[y * width:(y + 1) * width] for y in range(height)]


def side_by_side(left, right, gap=12):
    height = max(len(left), len(right))
    white = (255, 255, 255)
    def row(image, y):
        width = len(image[0])
        return image[y] if y < len(image) else [white] * width
    return [row(left, y) + [white] * gap + row(right, y) for y in range(height)]


def write_png(path, rows):
    height, width = len(rows), len(rows[0])
    raw = b"".join(b"\x00" + bytes(c for pixel in row for c in pixel) for row in rows)
    def chunk(kind, payload):
        body = kind + payload
        return struct.pack(">I", len(payload)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


def png_pixels(path):
    """Header and decompressed image data of a PNG written by write_png()."""
    with open(path, "rb") as f:
        data = f.read()
    chunks, at = {}, 8
    while at < len(data):
        length = struct.unpack(">I", data[at:at + 4])[0]
        kind = data[at + 4:at + 8]
        chunks[kind] = chunks.get(kind, b"") + data[at + 8:at + 8 + length]
        at += 12 + length
    return chunks[b"IHDR"], zlib.decompress(chunks[b"IDAT"])


def histogram_svg(path, panels):
    """One panel per mesh: share of faces per q bin (width 0.05), before (grey) and after (green)."""
    bins, panel_width, panel_height, left, bottom, top = 20, 300, 190, 46, 34, 26
    width = len(panels) * (panel_width + 20) + 10
    height = panel_height + 40
    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" '
           'font-size="11">' % (width, height), '<rect width="100%" height="100%" fill="white"/>']
    for index, (title, before, after) in enumerate(panels):
        x0 = 10 + index * (panel_width + 20)
        counts = []
        for values in (before, after):
            c = [0] * bins
            for q in values:
                c[min(int(q * bins), bins - 1)] += 1
            counts.append([100.0 * n / len(values) for n in c])
        peak = max(max(c) for c in counts)
        step = 10 if peak > 20 else 5
        ceiling = step * math.ceil(peak / step)
        plot_w, plot_h = panel_width - left - 10, panel_height - bottom - top
        def px(q):
            return x0 + left + q * plot_w
        def py(share):
            return top + plot_h - share / ceiling * plot_h
        out.append('<text x="%.1f" y="16" text-anchor="middle" font-size="12">%s</text>'
                   % (x0 + left + plot_w / 2, title))
        for share in range(0, int(ceiling) + 1, step):
            out.append('<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#ddd"/>'
                       % (px(0), py(share), px(1), py(share)))
            out.append('<text x="%.1f" y="%.1f" text-anchor="end">%d %%</text>' % (px(0) - 4, py(share) + 4, share))
        for series, (c, color) in enumerate(zip(counts, ("#9a9a9a", "#1a9850"))):
            for b, share in enumerate(c):
                bar = plot_w / bins / 2
                x = px(b / bins) + series * bar
                out.append('<rect x="%.2f" y="%.2f" width="%.2f" height="%.2f" fill="%s"/>'
                           % (x, py(share), bar - 0.5, py(0) - py(share), color))
        out.append('<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="black"/>' % (px(0), py(0), px(1), py(0)))
        for q in (0, 0.25, 0.5, 0.75, 1):
            out.append('<text x="%.1f" y="%.1f" text-anchor="middle">%g</text>' % (px(q), py(0) + 14, q))
        out.append('<text x="%.1f" y="%.1f" text-anchor="middle">aspect ratio q</text>'
                   % (px(0.5), py(0) + 28))
        out.append('<rect x="%.1f" y="%.1f" width="10" height="10" fill="#9a9a9a"/>' % (px(0.02), top - 2))
        out.append('<text x="%.1f" y="%.1f">before</text>' % (px(0.02) + 14, top + 7))
        out.append('<rect x="%.1f" y="%.1f" width="10" height="10" fill="#1a9850"/>' % (px(0.22), top - 2))
        out.append('<text x="%.1f" y="%.1f">after</text>' % (px(0.22) + 14, top + 7))
    out.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def main():
    arguments = [a for a in sys.argv[1:] if a != "--check"]
    check = "--check" in sys.argv[1:]
    build = arguments[0] if arguments else os.path.join(ROOT, "build")
    tool = os.path.join(build, "examples", "Polygon_mesh_processing_ILSA", "ilsa_smooth")
    if not os.path.exists(tool):
        sys.exit("make_figures.py: no ilsa_smooth in " + build + " (build the project first)")
    work = os.path.join(build, "figures")
    os.makedirs(work, exist_ok=True)
    output = os.path.join(work, "made") if check else FIG
    os.makedirs(output, exist_ok=True)
    panels = []
    for name, mesh, yaw, pitch, roll, width, edges in FIGURES:
        before_ply, after_ply = os.path.join(work, name + "_before.ply"), os.path.join(work, name + "_after.ply")
        run_tool(tool, os.path.join(MESHES, mesh), before_ply, "--iterations", "0")
        report = run_tool(tool, os.path.join(MESHES, mesh), after_ply)
        before, after = read_ply(before_ply), read_ply(after_ply)
        box = [tuple(min(p[i] for p in before[0]) for i in range(3))]
        left = render(before[0], before[1], yaw, pitch, roll, width, edges, box)
        right = render(after[0], after[1], yaw, pitch, roll, width, edges, box)
        write_png(os.path.join(output, "ilsa_%s_quality.png" % name), side_by_side(left, right))
        q = [[aspect_ratio(*(m[0][i] for i in f[0])) for f in m[1]] for m in (before, after)]
        panels.append(("%s (%d faces)" % (mesh, len(q[0])), q[0], q[1]))
        print("%s: %s" % (mesh, " | ".join(l for l in report.splitlines() if l.startswith(("before", "after")))))
        if name == "fandisk":
            write_png(os.path.join(output, "ilsa_package.png"), render(after[0], after[1], yaw, pitch, roll, 120, False, box))
    histogram_svg(os.path.join(output, "ilsa_quality_histogram.svg"), panels)
    if not check:
        print("figures written to " + FIG)
        return
    stale = []
    for name in sorted(os.listdir(output)):
        made, kept = os.path.join(output, name), os.path.join(FIG, name)
        if not os.path.exists(kept):
            stale.append(name + " (missing in fig)")
        elif name.endswith(".png") and png_pixels(made) != png_pixels(kept):
            stale.append(name)
        elif name.endswith(".svg") and open(made).read() != open(kept).read():
            stale.append(name)
    if stale:
        sys.exit("make_figures.py: out of date, rerun the script: " + ", ".join(stale))
    print("figures up to date")


if __name__ == "__main__":
    main()
