"""The report's one HTML page: what was run, the summary table and every figure with its
caption, each figure shown as PNG and linked to its SVG. Self-contained apart from the figure
files beside it: no script, no external style sheet or font."""
from __future__ import annotations

import html
import pathlib

from reports.style import SavedFigure

_STYLE = """
body { font-family: "DejaVu Sans", Arial, sans-serif; margin: 2em auto; max-width: 1250px; color: #222;
       line-height: 1.45; padding: 0 1em; }
h1 { margin-bottom: 0.2em; }
p.sources { color: #555; font-size: 0.92em; }
nav a { margin-right: 1.2em; }
table.summary { border-collapse: collapse; font-size: 0.88em; margin: 1em 0 2em; }
table.summary th, table.summary td { border: 1px solid #ccc; padding: 0.3em 0.55em; text-align: left; }
table.summary thead th { background: #f0f0f0; }
table.summary td.best { background: #e3f4e1; font-weight: bold; }
table.summary td.winner { font-weight: bold; }
table.summary td.missing { color: #aaa; text-align: center; }
span.direction { color: #777; font-size: 0.9em; }
figure { margin: 0 0 2.5em; }
figure img { max-width: 100%; height: auto; border: 1px solid #ddd; }
figcaption { font-size: 0.92em; color: #333; max-width: 1100px; }
figcaption a { margin-left: 0.4em; }
p.missing { color: #8a5a00; }
"""


def write_page(out_dir: pathlib.Path, figures: list[SavedFigure], summary_html: str, sources: list[str],
               missing: list[str]) -> pathlib.Path:
    """Writes out_dir/index.html; `sources` says which files the report was made from, `missing`
    which sections could not be drawn and why."""
    nav = "".join(f'<a href="#{f.stem}">{html.escape(f.title)}</a>' for f in figures)
    sections = []
    for f in figures:
        sections.append(
            f'<figure id="{f.stem}"><h2>{html.escape(f.title)}</h2>'
            f'<img src="{f.stem}.png" alt="{html.escape(f.title)}">'
            f'<figcaption>{html.escape(f.caption)} <a href="{f.stem}.svg">SVG</a></figcaption></figure>')
    missing_html = "".join(f'<p class="missing">{html.escape(text)}</p>' for text in missing)
    page = f"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<link rel="icon" href="data:,">
<title>curvebench report</title>
<style>{_STYLE}</style>
</head>
<body>
<h1>curvebench report</h1>
<p class="sources">Made from: {html.escape('; '.join(sources))}.</p>
<nav><a href="#summary">Summary</a>{nav}</nav>
<h2 id="summary">Which method is best under which condition</h2>
<p>From the same files as the figures below. The best value of each line is shaded; ties share
first place. A run that failed (error, timeout, crash) counts as unsuccessful in the shares and
is left out of the means.</p>
{summary_html}
{missing_html}
{''.join(sections)}
</body>
</html>
"""
    path = out_dir / "index.html"
    path.write_text(page)
    return path
