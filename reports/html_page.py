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
table.summary, table.details, table.gallery-links { border-collapse: collapse; font-size: 0.85em;
                                                    margin: 0.6em 0 1.2em; }
table th, table td { border: 1px solid #ccc; padding: 0.3em 0.5em; text-align: left; vertical-align: top; }
thead th { background: #f0f0f0; }
tr.condition-start > * { border-top: 2px solid #888; }
tr.agreement td { background: #f7f7f7; font-style: italic; }
div.rule { font-weight: normal; color: #555; font-size: 0.88em; max-width: 17em; }
span.method { font-weight: bold; }
div.value { color: #333; font-size: 0.92em; }
td.separated { background: #e3f4e1; }
td.unseparated { background: #fbf3dc; }
td.best { background: #e3f4e1; }
td.missing { color: #999; text-align: center; }
span.direction { color: #777; font-size: 0.9em; }
details { margin: 0.4em 0; }
details summary { cursor: pointer; color: #1a4d8f; }
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
            f'<figcaption>{html.escape(f.caption)} <a href="{f.stem}.svg">SVG</a></figcaption>{f.extra_html}</figure>')
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
<p>From the same files as the figures below; each condition's rule is stated in its cell and in
reports/README.md, and each row links to the figures it summarises. Per measure: every method's
median over its runs with the interquartile range [25%, 75%], and the share of its runs within
the stated tolerance of the best method on the same input. Only methods scored on at least 90%
of the condition's inputs are ranked (medians over different inputs do not compare); the best
has the best median (then the larger share) among those no other beats head to head, the
runner-up is the next ranked method of another algorithm. Best and
runner-up are <em>separated</em> (green) when, against every other method, the best is better by
more than the tolerance on at least 3 more of the inputs both ran than it is worse, so that no
single run can reverse the verdict; otherwise (amber) the row says why not.
A failed run (error, timeout, crash) counts as the worst value; a metric a method does not
define (edge F1 with vertices of its own, L2 on open curves) leaves it out of that measure. No
mean is used: one run cannot move a median or more than one head-to-head count. A method run
with a parameter grid appears at its default and at the grid's best setting under the condition
(labelled with the winning values; chosen on the same runs, so an optimistic bound; where the grid
ran on fewer inputs, with the default's median on those same inputs). Dominant
points: FOM is median CR / median ISE, because ISE is near 0 on some runs and one run's ratio
would decide a mean of ratios.</p>
{summary_html}
{missing_html}
{''.join(sections)}
</body>
</html>
"""
    path = out_dir / "index.html"
    path.write_text(page)
    return path
