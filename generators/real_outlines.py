"""Real outlines that curvebench makes itself, on a fresh machine, from a dependency it already
has: glyph outlines of the DejaVu Sans font that matplotlib ships (holes and sharp corners
included), and binary PNG silhouettes traced with contourpy (a matplotlib dependency). Both
are written as rings text files for `curvebench generate --family outline --input FILE`:
one vertex "x y" per line, a blank line between rings. No shape data lives in the repository.

    python generators/real_outlines.py glyphs --out DIR [--chars "ABR&@8gs"]
        one file glyph_<codepoint>.rings per character (the default real-shape set)
    python generators/real_outlines.py png IMAGE.png --out FILE.rings
        the outer contours and holes of the silhouette; the background is the colour most
        common on the image border. An image with no shape is an error (exit status 1).
"""
import argparse
import sys
from pathlib import Path

import numpy as np

DEFAULT_CHARS = "ABDRSaegs&@8%"


def write_rings(path, rings, comment):
    lines = [f"# {comment}"]
    for ring in rings:
        lines.extend(f"{x!r} {y!r}" for x, y in ring)
        lines.append("")
    Path(path).write_text("\n".join(lines) + "\n")


def glyph_rings(char):
    """The closed outlines of one glyph of DejaVu Sans, Bezier curves flattened by matplotlib."""
    from matplotlib.font_manager import FontProperties
    from matplotlib.textpath import TextPath

    path = TextPath((0, 0), char, size=1, prop=FontProperties(family="DejaVu Sans"))
    rings = []
    for polygon in path.to_polygons(closed_only=True):
        ring = [(float(x), float(y)) for x, y in polygon]
        if len(ring) > 1 and ring[0] == ring[-1]:
            ring.pop()
        if len(ring) >= 3:
            rings.append(ring)
    return rings


def silhouette_rings(image_path):
    """Outer contours and holes of a binary silhouette: contour at half height of the
    foreground mask, lightly blurred so that the pixel staircase does not read as corners."""
    import contourpy
    import matplotlib.image

    image = np.asarray(matplotlib.image.imread(image_path), dtype=float)
    if image.ndim == 3:
        has_alpha = image.shape[2] == 4 and image[..., 3].min() < image[..., 3].max()
        image = image[..., 3] if has_alpha else image[..., :3].mean(axis=2)
    border = np.concatenate([image[0], image[-1], image[:, 0], image[:, -1]])
    background = np.median(border)
    mask = (np.abs(image - background) > 0.5 * (image.max() - image.min())).astype(float)
    if image.max() == image.min() or not mask.any():
        raise ValueError(f"{image_path}: no shape in the image")
    mask = np.pad(mask, 2)
    for _ in range(2):  # 3x3 box blur, twice
        padded = np.pad(mask, 1, mode="edge")
        mask = sum(padded[1 + dy : padded.shape[0] - 1 + dy, 1 + dx : padded.shape[1] - 1 + dx]
                   for dy in (-1, 0, 1) for dx in (-1, 0, 1)) / 9.0
    lines = contourpy.contour_generator(z=mask).lines(0.5)
    rings = []
    for line in lines:
        ring = [(float(x), -float(y)) for x, y in line]  # rows grow downwards
        if len(ring) > 1 and ring[0] == ring[-1]:
            ring.pop()
        if len(ring) >= 3:
            rings.append(ring)
    if not rings:
        raise ValueError(f"{image_path}: no shape in the image")
    return rings


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    commands = parser.add_subparsers(dest="command", required=True)
    glyphs = commands.add_parser("glyphs", help="glyph outlines of DejaVu Sans")
    glyphs.add_argument("--out", required=True, help="directory to write glyph_<codepoint>.rings into")
    glyphs.add_argument("--chars", default=DEFAULT_CHARS, help=f"characters (default {DEFAULT_CHARS!r})".replace("%", "%%"))  # argparse formats help with %
    png = commands.add_parser("png", help="a binary PNG silhouette")
    png.add_argument("image")
    png.add_argument("--out", required=True, help="rings file to write")
    args = parser.parse_args(argv)
    try:
        if args.command == "glyphs":
            out = Path(args.out)
            out.mkdir(parents=True, exist_ok=True)
            for char in args.chars:
                rings = glyph_rings(char)
                if rings:
                    write_rings(out / f"glyph_{ord(char):04x}.rings", rings, f"DejaVu Sans glyph {char!r} (matplotlib TextPath)")
        else:
            write_rings(args.out, silhouette_rings(args.image), f"silhouette of {Path(args.image).name}")
    except (OSError, ValueError) as error:
        print(f"real_outlines: error: {error}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
