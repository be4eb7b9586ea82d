#!/usr/bin/env python3
"""Draws the audit report: python3 report.py audit.json report.html

A self-contained HTML page (charts as embedded PNG, no network) from incidence-audit's JSON
(schema: audit.schema.json next to this file). Charts are drawn with matplotlib."""
import base64
import html
import io
import json
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STYLE = {  # method -> (colour, line style)
    "exact": ("#000000", "-"),
    "conservative": ("#1f77b4", "--"),
    "aggressive": ("#ff7f0e", "--"),
    "approximate": ("#d62728", "-"),
    "signs_in_double": ("#9467bd", ":"),
    "cgal_epick": ("#2ca02c", "-."),
}
EXTRA = ["#8c564b", "#e377c2", "#17becf", "#bcbd22", "#7f7f7f"]


def style(name, i):
    return STYLE.get(name, (EXTRA[i % len(EXTRA)], "-"))


def png(fig):
    buf = io.BytesIO()
    # fixed margins (set where each figure is made), not bbox_inches="tight": measuring the tight
    # box draws every figure twice, half of the report's time
    fig.savefig(buf, format="png", dpi=90)
    plt.close(fig)
    return base64.b64encode(buf.getvalue()).decode("ascii")


def img(data, alt):
    return f'<img alt="{html.escape(alt)}" src="data:image/png;base64,{data}">'


def esc(x):
    return html.escape(str(x))


def offset_text(x):
    if x == 0:
        return "0"
    e = math.log2(abs(x))
    return f"2<sup>{int(e)}</sup>" if e == int(e) else f"{x:g}"


def pct(num, den):
    return 100.0 * num / den if den else 0.0


def table(head, rows, cls=""):
    out = [f'<table class="{cls}"><tr>' + "".join(f"<th>{esc(h)}</th>" for h in head) + "</tr>"]
    for r in rows:
        out.append("<tr>" + "".join(f"<td>{c}</td>" for c in r) + "</tr>")
    out.append("</table>")
    return "\n".join(out)


def stability_section(d):
    st = d["stability"]
    levels = st["levels"]
    sep = [i for i, l in enumerate(levels) if l["kind"] == "separation"]
    ulp = [i for i, l in enumerate(levels) if l["kind"] == "ulp"]
    settings = st["settings"]
    parts = ["<h2 id=stability>Stability: where each method starts to fail</h2>",
             f"<p>Each family starts from configurations that touch exactly (built from small integers), "
             f"then moves the second shape by 2<sup>-k</sup> of the object size in a random direction "
             f"(k = 0..60, left), or moves one coordinate by 0..8 ulps (right). Every point is "
             f"{st['cases_per_level_and_setting']} cases in each of {len(settings)} coordinate settings "
             f"(offsets from the origin and scales 2<sup>e</sup>: "
             + ", ".join(f"offset {offset_text(s['offset'])}, scale 2<sup>{s['scale_exp']}</sup>" for s in settings)
             + "). Wrong means different from the exact tier. Conservative may only err towards yes and "
             "aggressive only towards no (dashed): those are their contracts, and a broken contract is "
             "counted separately.</p>"]
    summary = []
    for fam in st["families"]:
        fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 3.6), gridspec_kw={"width_ratios": [3, 1.3]})
        fig.subplots_adjust(left=0.07, right=0.99, bottom=0.14, top=0.92, wspace=0.15)
        for i, m in enumerate(fam["methods"]):
            c, ls = style(m["name"], i)
            y1 = [pct(m["wrong"][j], m["cases"][j]) for j in sep]
            y2 = [pct(m["wrong"][j], m["cases"][j]) for j in ulp]
            ax1.plot([levels[j]["k"] for j in sep], y1, ls, color=c, label=m["name"], lw=1.4)
            ax2.plot([levels[j]["ulps"] for j in ulp], y2, ls, color=c, marker=".", lw=1.2)
            total = sum(m["wrong"])
            cases = sum(m["cases"])
            summary.append([esc(fam["name"]), esc(m["name"]), esc(m["kind"]), f"{total:,}", f"{cases:,}",
                            f"{sum(m['false_positive']):,}", f"{sum(m['false_negative']):,}",
                            f'<b class="{"bad" if m["contract_violations"] else "ok"}">{m["contract_violations"]}</b>'])
        unc = [pct(fam["uncertain"][j], fam["cases_per_level"]) for j in sep]
        ax1.plot([levels[j]["k"] for j in sep], unc, color="#aaaaaa", lw=3, alpha=0.5, label="filter uncertain")
        ax1.set_xlabel("separation 2^-k of the object size: k")
        ax1.set_ylabel("wrong answers, % of cases")
        ax1.set_title(f"{fam['name']}: approaching the boundary")
        ax1.set_xlim(0, 60)
        ax1.grid(alpha=0.3)
        ax2.set_xlabel("ulps moved from exactly touching")
        ax2.set_title("ulp perturbations")
        ax2.grid(alpha=0.3)
        ax1.legend(fontsize=7, ncol=2, loc="upper left")
        parts.append(f"<h3>{esc(fam['name'])}</h3>" + img(png(fig), f"stability curves for {fam['name']}"))
        rows = []
        for m in fam["methods"]:
            rows.append([esc(m["name"])] + [f"{s['wrong']:,} / {s['cases']:,}" for s in m["by_setting"]])
        parts.append("<details><summary>wrong answers by coordinate setting</summary>" + table(
            ["method"] + [f"offset {offset_text(s['offset'])}, scale 2<sup>{s['scale_exp']}</sup>" for s in settings], rows,
            "small") + "</details>")
    common = ["exact", "conservative", "aggressive", "approximate", "signs_in_double", "cgal_epick"]
    head_rows = []
    for fam in st["families"]:
        by = {m["name"]: m for m in fam["methods"]}

        def cell(m):
            w, n = sum(m["wrong"]), sum(m["cases"])
            cls = "bad" if m["contract_violations"] else ("ok" if w == 0 else "")
            return f'<span class="{cls}">{pct(w, n):.2f}%</span>'
        alts = ", ".join(f"{esc(m['name'])} {cell(m)}" for m in fam["methods"] if m["kind"] == "alternative")
        head_rows.append([esc(fam["name"])] + [cell(by[c]) if c in by else "&ndash;" for c in common] + [alts or "&ndash;"])
    parts.insert(1, "<h3>Wrong answers over all levels and settings</h3>" + table(
        ["family"] + common + ["alternatives"], head_rows) +
        "<details><summary>counts per method (false yes, false no, contract violations)</summary>" + table(
        ["family", "method", "kind", "wrong", "cases", "false yes", "false no", "contract violations"], summary, "small") +
        "</details>")
    return "\n".join(parts)


def tradeoff_section(d):
    tr = d["tradeoff"]
    parts = ["<h2 id=tradeoff>Speed against accuracy</h2>",
             f"<p>Median ns per test over {tr['repetitions']} repetitions measured in this run "
             f"({esc(tr['timing'])}), against the error rate on a near-degenerate set "
             f"({tr['cases']} cases per family: separations 2<sup>-30</sup>..2<sup>-60</sup> and 0..8-ulp moves). "
             "Ringed points are the Pareto front: no other method is both as fast and as accurate.</p>"]
    fams = tr["families"]
    cols = 3
    rows_n = (len(fams) + cols - 1) // cols
    fig, axes = plt.subplots(rows_n, cols, figsize=(13, 3.6 * rows_n), squeeze=False)
    rows = []
    for k, fam in enumerate(fams):
        ax = axes[k // cols][k % cols]
        front = sorted([m for m in fam["methods"] if m["pareto"]], key=lambda m: m["ns_near"])
        for i, m in enumerate(fam["methods"]):
            c, _ = style(m["name"], i)
            x, y = m["ns_near"], 100 * m["error_rate_near"]
            ax.scatter([x], [y], color=c, s=36, zorder=3, edgecolors="black" if m["pareto"] else "none", linewidths=1.2)
            ax.annotate(m["name"], (x, y), fontsize=7, xytext=(3, 3), textcoords="offset points")
            rows.append([esc(fam["name"]), esc(m["name"]), esc(m["kind"]), f"{m['ns_near']:.1f}", f"{m['ns_random']:.1f}",
                         f"{100 * m['error_rate_near']:.3f}%", f"{100 * m['error_rate_random']:.3f}%",
                         "yes" if m["pareto"] else ""])
        ax.plot([m["ns_near"] for m in front], [100 * m["error_rate_near"] for m in front], color="#888", lw=1, zorder=2)
        ax.set_xscale("log")
        ax.set_yscale("symlog", linthresh=0.1)
        ax.set_ylim(0, 200)
        ax.set_title(fam["name"], fontsize=10)
        ax.set_xlabel("ns per test (near-degenerate)", fontsize=8)
        ax.set_ylabel("wrong, %", fontsize=8)
        ax.grid(alpha=0.3)
    for k in range(len(fams), rows_n * cols):
        axes[k // cols][k % cols].axis("off")
    # fixed margins in inches (tight_layout over this many panels takes seconds)
    height = 3.6 * rows_n
    fig.subplots_adjust(left=0.6 / 13, right=1 - 0.15 / 13, bottom=0.55 / height, top=1 - 0.35 / height,
                        wspace=0.22, hspace=0.95 / 2.7)
    parts.append(img(png(fig), "speed against accuracy, one panel per family"))
    parts.append(table(["family", "method", "kind", "ns near-degenerate", "ns random", "wrong near-degenerate",
                        "wrong random", "Pareto"], rows, "small"))
    return "\n".join(parts)


def scene_section(d):
    sc = d["scene"]
    adv = sc["advice"]
    parts = ["<h2 id=scene>Scene</h2>",
             f"<p><b>{esc(sc['file'])}</b>: {sc['vertices']:,} vertices, {sc['triangles']:,} triangles, "
             f"{sc['camera_rays']:,} camera rays.</p>",
             f'<div class="advice"><b>Advice: the {esc(adv["tier"])} tier.</b> {esc(adv["text"])}<br>'
             f'<b>Bounding volume:</b> {esc(adv["bounding_volume"])}</div>']
    ws = sc["workloads"]
    fig, axes = plt.subplots(1, len(ws), figsize=(3.2 * len(ws), 3.4), squeeze=False)
    for k, w in enumerate(ws):
        ax = axes[0][k]
        names = [m["name"] for m in w["methods"]]
        ax.barh(names, [m["ms"] for m in w["methods"]],
                color=[style(m["name"], i)[0] for i, m in enumerate(w["methods"])])
        for i, m in enumerate(w["methods"]):
            if m["wrong"]:
                ax.annotate(f"{m['wrong']:,} wrong", (m["ms"], i), fontsize=7, xytext=(2, -3), textcoords="offset points",
                            color="#b00")
        ax.set_title(w["name"], fontsize=10)
        ax.set_xlabel("ms for all tests", fontsize=8)
        ax.tick_params(labelsize=7)
        ax.invert_yaxis()
    fig.tight_layout()
    parts.append(img(png(fig), "scene time per method and workload"))
    for w in ws:
        rows = []
        for m in w["methods"]:
            rows.append([esc(m["name"]), esc(m["kind"]), f"{m['ms']:.1f}", f"{m['tests']:,}", f"{m['wrong']:,}",
                         f"{m['false_positive']:,}", f"{m['false_negative']:,}",
                         f"{m['holes']:,}" if w["holes_apply"] else "&ndash;"])
        parts.append(f"<h3>{esc(w['name'])}</h3><p>{esc(w['description'])}; {w['tests']:,} tests, "
                     f"{w['uncertain']:,} of them undecided by the filter.</p>" + table(
                         ["method", "kind", "ms", "tests", "wrong", "false yes", "false no",
                          "holes (rays hitting none of the triangles there)"], rows, "small"))
    bv = sc["bounding_volumes"]
    ours = [r for r in bv["rows"] if r["ours"]]
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 3.6))
    for i, r in enumerate(ours):
        c = EXTRA[i % len(EXTRA)] if "sphere" in r["kind"] else STYLE["conservative"][0]
        if r["test_ns"] > 0:  # the hull has no overlap test of its own here
            a1.scatter([r["test_ns"]], [r["volume_ratio"]], color=c, s=30)
            a1.annotate(r["kind"], (r["test_ns"], r["volume_ratio"]), fontsize=7, xytext=(3, 2), textcoords="offset points")
        a2.scatter([max(r["build_ms"], 1e-4)], [r["volume_ratio"]], color=c, s=30)
        a2.annotate(r["kind"], (max(r["build_ms"], 1e-4), r["volume_ratio"]), fontsize=7, xytext=(3, 2), textcoords="offset points")
    for r in bv["rows"]:
        if not r["ours"]:
            a2.scatter([max(r["build_ms"], 1e-4)], [r["volume_ratio"]], color="#2ca02c", marker="s", s=30)
            a2.annotate(r["kind"], (max(r["build_ms"], 1e-4), r["volume_ratio"]), fontsize=7, xytext=(3, 2),
                        textcoords="offset points", color="#2ca02c")
    a1.set_xlabel("ns per overlap test"), a1.set_ylabel("volume / convex hull volume"), a1.set_title("tightness against test cost")
    a2.set_xscale("log"), a2.set_xlabel("build ms"), a2.set_title("tightness against build time")
    for a in (a1, a2):
        a.set_yscale("log"), a.grid(alpha=0.3)
    fig.tight_layout()
    rows = [[esc(r["kind"]), esc(r["source"]), f"{r['build_ms']:.3f}", f"{r['volume_ratio']:.3f}",
             f"{r['area_ratio']:.3f}" if r["area_ratio"] > 0 else "&ndash;",
             f"{r['test_ns']:.1f}" if r["test_ns"] > 0 else "&ndash;",
             ("yes" if r["contains_all"] else '<b class="bad">NO</b>') if r["ours"] else "&ndash;"] for r in bv["rows"]]
    parts.append(f"<h3>Bounding volumes</h3><p>Relative to the convex hull ({bv['hull_vertices']:,} vertices). Every "
                 "volume of ours is checked exactly to contain every vertex.</p>" + img(png(fig), "bounding volumes") +
                 table(["volume", "construction", "build ms", "volume / hull", "area / hull", "ns per test",
                        "contains every vertex"], rows, "small"))
    return "\n".join(parts)


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: report.py audit.json report.html")
    with open(sys.argv[1]) as f:
        d = json.load(f)
    sections = []
    nav = []
    if "stability" in d:
        sections.append(stability_section(d))
        nav.append('<a href="#stability">stability</a>')
    if "tradeoff" in d:
        sections.append(tradeoff_section(d))
        nav.append('<a href="#tradeoff">speed against accuracy</a>')
    if "scene" in d:
        sections.append(scene_section(d))
        nav.append('<a href="#scene">scene</a>')
    fams = ", ".join(esc(f["name"]) for f in d["families"])
    verdict = ("every conservative and aggressive answer kept its contract"
               if d["contract_violations"] == 0 else f"{d['contract_violations']} contract violations")
    page = f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>incidence robustness audit</title>
<style>
body {{ font-family: sans-serif; margin: 2em auto; max-width: 1250px; color: #222; }}
img {{ max-width: 100%; display: block; margin: 0.5em 0; }}
table {{ border-collapse: collapse; margin: 0.5em 0 1.5em; }}
td, th {{ border: 1px solid #ccc; padding: 2px 8px; text-align: right; }}
td:first-child, th:first-child, td:nth-child(2) {{ text-align: left; }}
table.small {{ font-size: 12px; }}
.ok {{ color: #070; }} .bad {{ color: #b00; }}
.advice {{ background: #eef6ee; border-left: 4px solid #2a2; padding: 0.6em 1em; }}
nav a {{ margin-right: 1em; }}
</style></head>
<body>
<h1>incidence robustness audit</h1>
<p>{esc(d['command_line'])} &mdash; {d['seconds']:.1f} s. Families: {fams}. Result: <b>{esc(verdict)}</b>.</p>
<nav>{' '.join(nav)}</nav>
{''.join(sections)}
<script>
window.addEventListener("load", function () {{
  var imgs = Array.prototype.slice.call(document.images);
  var broken = imgs.filter(function (i) {{ return !i.complete || i.naturalWidth === 0; }}).length;
  document.body.setAttribute("data-images", String(imgs.length));
  document.body.setAttribute("data-images-broken", String(broken));
}});
</script>
</body></html>
"""
    with open(sys.argv[2], "w") as f:
        f.write(page)


if __name__ == "__main__":
    main()
