"""The summary as HTML: one table of which method is best under which condition (a row per
condition and measure, then whether the metrics agree), and per condition a details element with
every method's statistics and its head-to-head counts (summary_table.py computes them)."""
from __future__ import annotations

import html

from reports.robust_statistics import Comparison
from reports.summary_table import ConditionSummary, SummaryLine, beats


def summary_html(summaries: list[ConditionSummary], other_lines: list[SummaryLine], drawn: set[str]) -> str:
    """The summary table, then per condition every method's statistics (in a details element);
    rows link to those of their figures that were drawn (stems in `drawn`)."""
    head = ("<thead><tr><th>condition</th><th>measure</th><th>runs</th><th>best</th><th>runner-up</th>"
            "<th>verdict</th></tr></thead>")
    body = []
    for summary in summaries:
        span = len(summary.lines) + 1
        about = _joined([html.escape(summary.rule), f"{summary.runs} runs on {summary.inputs} inputs",
                         _figure_links(summary.figures, drawn),
                         f'<a href="#details-{_anchor(summary.name)}">every method</a>'])
        body.append(f'<tr class="condition-start"><th scope="row" rowspan="{span}">{html.escape(summary.name)}'
                    f'<div class="rule">{about}</div></th>' + _line_cells(summary.lines[0]) + "</tr>")
        for line in summary.lines[1:]:
            body.append("<tr>" + _line_cells(line) + "</tr>")
        body.append(f'<tr class="agreement"><td colspan="5">{html.escape(summary.agreement)}</td></tr>')
    for line in other_lines:
        details = (f'<a href="#details-{_anchor(line.condition)}">every method</a>' if line.comparison is not None
                   else "")
        about = _joined([html.escape(line.rule), _figure_links(line.figures, drawn), details])
        body.append(f'<tr class="condition-start"><th scope="row">{html.escape(line.condition)}<div class="rule">'
                    f'{about}</div></th>' + _line_cells(line) + "</tr>")
    table = f'<table class="summary">{head}<tbody>{"".join(body)}</tbody></table>'
    return table + "".join(_details_html(summary) for summary in summaries) + \
        "".join(_line_details_html(line) for line in other_lines if line.comparison is not None)


def _figure_links(stems: tuple[str, ...], drawn: set[str]) -> str:
    """'figures: a, b' (links) for the stems that were drawn, '' if none."""
    links = ", ".join(f'<a href="#{stem}">{stem}</a>' for stem in stems if stem in drawn)
    return f"figures: {links}" if links else ""


def _joined(parts: list[str]) -> str:
    """The non-empty parts (HTML), '; ' between them."""
    return "; ".join(part for part in parts if part)


def _anchor(name: str) -> str:
    return "".join(c if c.isalnum() else "-" for c in name.lower())


def _line_cells(line: SummaryLine) -> str:
    direction = "higher is better" if line.higher_is_better else "lower is better"
    tolerance = (f", tie within {line.comparison.metric.tolerance_text()}" if line.comparison is not None else "")

    def method_cell(label: str | None) -> str:
        if label is None:
            return '<td class="missing">-</td>'
        return (f'<td><span class="method">{html.escape(label)}</span><div class="value">'
                f'{html.escape(line.cells[label])}</div></td>')

    verdict_class = "separated" if line.separated else "unseparated"
    return (f'<td>{html.escape(line.measure)} <span class="direction">({direction}{tolerance})</span></td>'
            f'<td>{html.escape(line.runs_text)}</td>{method_cell(line.best)}{method_cell(line.runner_up)}'
            f'<td class="{verdict_class}">{html.escape(line.verdict)}</td>')


def _head_to_head_counts(comparison: Comparison, label: str) -> tuple[int, int]:
    """How many other methods this one beats, and is beaten by, head to head (summary_table.beats)."""
    others = [other for other in comparison.statistics if other != label]
    return (sum(beats(comparison, label, other) for other in others),
            sum(beats(comparison, other, label) for other in others))


def _details_html(summary: ConditionSummary) -> str:
    labels = [v.label for v in summary.variants]
    head = "".join(f"<th>{html.escape(line.measure)}</th>" for line in summary.lines)
    body = []
    for label in labels:
        cells = []
        for line in summary.lines:
            if line.comparison is None or label not in line.comparison.statistics:
                cells.append('<td class="missing">undefined</td>')
                continue
            wins, losses = _head_to_head_counts(line.comparison, label)
            best_class = ' class="best"' if label == line.best else ""
            cells.append(f"<td{best_class}>{html.escape(line.cells[label])}; head to head beats {wins}, "
                         f"is beaten by {losses}</td>")
        body.append(f"<tr><th scope=\"row\">{html.escape(label)}</th>{''.join(cells)}</tr>")
    return (f'<details id="details-{_anchor(summary.name)}"><summary>{html.escape(summary.name)}: every method '
            f"({summary.runs} runs on {summary.inputs} inputs)</summary><table class=\"details\"><thead><tr>"
            f"<th>method</th>{head}</tr></thead><tbody>{''.join(body)}</tbody></table></details>")


def _line_details_html(line: SummaryLine) -> str:
    body = "".join(f"<tr><th scope=\"row\">{html.escape(label)}</th><td>{html.escape(line.cells[label])}</td></tr>"
                   for label in line.comparison.ranking if label in line.cells)
    return (f'<details id="details-{_anchor(line.condition)}"><summary>{html.escape(line.condition)}: every method'
            f"</summary><table class=\"details\"><thead><tr><th>method</th><th>{html.escape(line.measure)}</th></tr>"
            f"</thead><tbody>{body}</tbody></table></details>")
