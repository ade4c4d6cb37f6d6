"""The HTML page of a validation run: the table of records and one figure per case.

    python3 -m bemcontact.report VALIDATE_JSON OUTPUT_DIR
    bemcontact validate --report OUTPUT_DIR      (runs the cases, then this)

A case whose records vary a mesh size (elements, h, n, ...) gets its error against that
size on log scales, one line per quantity; the others get each record's error as a
fraction of its tolerance (a bar past 1 is a failure).
"""
import collections
import html
import json
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

MESH_SIZE_KEYS = ("elements", "contact_elements", "elements_per_arc", "n", "h")


def _number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def _mesh_key(records):
    for key in MESH_SIZE_KEYS:
        values = {_number(r["params"].get(key)) for r in records}
        if None not in values and len(values) >= 2:
            return key
    return None


def _label(record, skip=()):
    params = ", ".join(f"{k}={v}" for k, v in record["params"].items() if k not in skip)
    return f"{record['quantity']} ({params})" if params else record["quantity"]


def case_figure(name, records, path):
    counted = [r for r in records if r.get("tolerance") is not None and r.get("error") is not None]
    if not counted:
        return None
    key = _mesh_key(counted)
    if key:
        counted = [r for r in counted if r.get("comparison") != "at_least"]  # orders, not errors
        fig, ax = plt.subplots(figsize=(7, 4.5))
        lines = collections.defaultdict(list)
        for r in counted:
            group = (r["quantity"],) + tuple(f"{k}={v}" for k, v in sorted(r["params"].items()) if k != key
                                               and _number(v) is None)
            lines[group].append((_number(r["params"][key]), abs(r["error"]), r["tolerance"]))
        for group, points in lines.items():
            points.sort()
            x, err, tol = (np.array(v) for v in zip(*points))
            shown = ax.loglog(x, np.maximum(err, 1e-16), "o-", ms=3, label=" ".join(group))
            ax.loglog(x, tol, ":", color=shown[0].get_color(), lw=0.8)
        ax.set_xlabel(key)
        ax.set_ylabel("|error| (dotted: tolerance)")
        ax.set_title(f"{name}: error against mesh size", fontsize=9)
        if len(lines) <= 12:
            ax.legend(fontsize=6)
    else:
        height = max(2.5, 0.18 * len(counted) + 1.0)
        fig, ax = plt.subplots(figsize=(8, min(height, 30)))
        ratios = [abs(r["error"]) / r["tolerance"] if r["tolerance"] > 0 else 0.0 for r in counted]
        if any(r.get("comparison") == "at_least" for r in counted):
            ratios = [r["tolerance"] / max(abs(r["computed"]), 1e-300) if r.get("comparison") == "at_least" else q
                      for r, q in zip(counted, ratios)]
        colours = ["tab:green" if r["passed"] else "tab:red" for r in counted]
        y = np.arange(len(counted))
        ax.barh(y, np.maximum(ratios, 1e-6), color=colours)
        ax.set_xscale("log")
        ax.axvline(1.0, color="k", lw=0.8)
        ax.set_yticks(y)
        ax.set_yticklabels([_label(r) for r in counted], fontsize=6)
        ax.invert_yaxis()
        ax.set_xlabel("|error| / tolerance (past 1: fails)")
        ax.set_title(f"{name}: each record against its tolerance", fontsize=9)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
    return path


def _cell(value):
    if isinstance(value, float):
        return f"{value:.6g}"
    return html.escape("" if value is None else str(value))


def write_report(records, out_dir):
    out = pathlib.Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    cases = collections.OrderedDict()
    for r in records:
        cases.setdefault(r["case"], []).append(r)
    counted = [r for r in records if r.get("passed") is not None]
    failed = sum(1 for r in counted if not r["passed"])
    parts = ["<!DOCTYPE html><html><head><meta charset='utf-8'><title>bemcontact validation</title>",
             "<style>body{font-family:sans-serif;margin:2em}table{border-collapse:collapse;font-size:12px}"
             "td,th{border:1px solid #ccc;padding:2px 6px;text-align:right}td.l{text-align:left}"
             ".no{background:#fdd}.yes{background:#efe}</style></head><body>",
             f"<h1>bemcontact validation</h1><p>{len(counted) - failed} passed, {failed} failed, "
             f"{len(records) - len(counted)} reported only, in {len(cases)} cases.</p><ul>"]
    parts += [f"<li><a href='#{html.escape(c)}'>{html.escape(c)}</a></li>" for c in cases]
    parts.append("</ul>")
    for name, rows in cases.items():
        parts.append(f"<h2 id='{html.escape(name)}'>{html.escape(name)}</h2>")
        figure = case_figure(name, rows, out / f"{name}.png")
        if figure:
            parts.append(f"<img src='{html.escape(figure.name)}' alt='{html.escape(name)}'>")
        parts.append("<table><tr><th>params</th><th>quantity</th><th>computed</th><th>reference</th><th>error</th>"
                     "<th>tolerance</th><th>pass</th></tr>")
        for r in rows:
            verdict = "info" if r.get("passed") is None else ("yes" if r["passed"] else "NO")
            style = {"yes": "yes", "NO": "no"}.get(verdict, "")
            params = " ".join(f"{k}={v}" for k, v in r["params"].items())
            parts.append(f"<tr class='{style}'><td class='l'>{_cell(params)}</td><td class='l'>{_cell(r['quantity'])}"
                         f"</td><td>{_cell(r.get('computed'))}</td><td>{_cell(r.get('reference'))}</td>"
                         f"<td>{_cell(r.get('error'))}</td><td>{_cell(r.get('tolerance'))}</td><td>{verdict}</td></tr>")
        parts.append("</table>")
    parts.append("</body></html>\n")
    page = out / "index.html"
    page.write_text("".join(parts), encoding="utf-8")
    return page


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 2:
        print("usage: python3 -m bemcontact.report VALIDATE_JSON OUTPUT_DIR", file=sys.stderr)
        return 2
    with open(argv[0], encoding="utf-8") as f:
        records = json.load(f)
    page = write_report(records, argv[1])
    print(f"  wrote {page}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
