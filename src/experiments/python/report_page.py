"""The HTML report of one run: gdpn's tables and matplotlib plots (SVG) in one page.

gdpn calls page(text) with the run as JSON text (the report, the timeline of occurrences
and tokens, the signals) and writes the page it returns. The page loads nothing from
elsewhere: its style and its plots are inside it.
"""

import html
import io
import json
import math
import re

import matplotlib

matplotlib.use("svg")
import matplotlib.pyplot as plt  # noqa: E402

# the colours each kind of plot uses (a test finds them in a screenshot of the page)
TOKENS = "#1f77b4"
GANTT = "#ff7f0e"
BOUND = "#9a9a9a"
MEASURED = "#d62728"
SIGNALS = ["#9467bd", "#17becf", "#bcbd22"]
LEVELS = "#0b7a8a"
THROUGHPUT = ["#2ca02c", "#8c564b", "#e377c2", "#393b79", "#e6550d", "#6b6ecf"]

MAX_PLACES = 12        # token plots
MAX_ROWS = 30          # transitions in the Gantt chart
MAX_BARS = 20000       # occurrences drawn in it
MAX_LANES = 8          # lanes of one row, for occurrences at once
MAX_SERIES = 6         # transitions in the throughput plot
MAX_CYCLES = 20        # cycles beside their bounds
MAX_SIGNALS = 24       # signal plots
MAX_TABLE = 200        # rows of a table
WIDTH = 10.0           # inches of a plot


def esc(text):
    return html.escape(str(text), quote=True)


def number(value, digits=4):
    """A number as a reader wants it: whole numbers whole, others with `digits` significant."""
    if value is None:
        return "–"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, int):
        return f"{value:,}".replace(",", "\u2009")
    if not math.isfinite(value):
        return str(value)
    if value == int(value) and abs(value) < 1e15:
        return f"{int(value):,}".replace(",", "\u2009")
    return f"{value:.{digits}g}"


def svg(fig):
    """A figure as inline SVG (no XML prologue, no date: the same run gives the same page)."""
    out = io.StringIO()
    fig.savefig(out, format="svg", bbox_inches="tight", metadata={"Date": None})
    plt.close(fig)
    text = out.getvalue()
    text = text[text.find("<svg"):]
    # matplotlib's RDF metadata says only that matplotlib drew it
    return re.sub(r"\s*<metadata>.*?</metadata>", "", text, count=1, flags=re.S)


def style():
    plt.rcParams.update({
        "svg.hashsalt": "gdpn",
        "svg.fonttype": "path",
        "font.size": 9,
        "axes.spines.top": False,
        "axes.spines.right": False,
        "axes.grid": True,
        "grid.color": "#e6e6e6",
        "grid.linewidth": 0.6,
        "axes.axisbelow": True,
    })


PREFIX = ""  # the page (folder) every name is under, left out of the plots' labels


def common_prefix(names):
    """The longest "page/" every name starts with ("" when they share none)."""
    names = list(names)
    if not names:
        return ""
    first = names[0]
    end = first.rfind("/") + 1
    while end > 0 and not all(n.startswith(first[:end]) and len(n) > end for n in names):
        end = first.rfind("/", 0, end - 1) + 1
    return first[:end]


def short(name, width=48):
    if PREFIX and name.startswith(PREFIX):
        name = name[len(PREFIX):]
    return name if len(name) <= width else "…" + name[-(width - 1):]


MAX_POINTS = 4000  # steps of one token plot drawn as they are; more are thinned


def thin(changes, end):
    """At most about 2 * MAX_POINTS of a place's (time, tokens) steps: past that, each of
    MAX_POINTS windows keeps its lowest and highest count, so every peak still shows."""
    if len(changes) <= MAX_POINTS:
        return changes
    width = max(end, changes[-1][0]) / MAX_POINTS or 1.0
    out, window = [], {}
    for t, n in changes:
        window.setdefault(min(int(t / width), MAX_POINTS - 1), []).append((t, n))
    for k in sorted(window):
        pts = window[k]
        lo = min(pts, key=lambda p: p[1])
        hi = max(pts, key=lambda p: p[1])
        out += sorted({lo, hi})
    return out


def varies(changes):
    return len({c[1] for c in changes}) > 1


def table(headers, rows, numeric, total=None, note=""):
    """An HTML table; `numeric` says which columns align right."""
    out = ['<div class="wide"><table><thead><tr>']
    for h, n in zip(headers, numeric):
        out.append(f'<th class="{"num" if n else ""}">{esc(h)}</th>')
    out.append("</tr></thead><tbody>")
    for row in rows[:MAX_TABLE]:
        out.append("<tr>")
        for cell, n in zip(row, numeric):
            out.append(f'<td class="{"num" if n else ""}">{esc(cell)}</td>')
        out.append("</tr>")
    out.append("</tbody></table></div>")
    total = len(rows) if total is None else total
    if total > MAX_TABLE:
        out.append(f'<p class="note">The first {MAX_TABLE} of {total} rows.{esc(note)}</p>')
    elif note:
        out.append(f'<p class="note">{esc(note)}</p>')
    return "".join(out)


def section(anchor, title, body, caption=""):
    cap = f'<p class="caption">{caption}</p>' if caption else ""
    return f'<section id="{anchor}"><h2>{esc(title)}</h2>{cap}{body}</section>'


def tokens_plot(run):
    tl = run["timeline"]
    end = run["time"]
    places = [p for p in tl["places"] if varies(p["changes"])]
    if not places:
        return None, "No place changed its tokens during the run."
    # the busiest places first; ties in declaration order
    shown = sorted(places, key=lambda p: -len(p["changes"]))[:MAX_PLACES]
    order = {p["name"]: i for i, p in enumerate(tl["places"])}
    shown.sort(key=lambda p: order[p["name"]])
    fig, axes = plt.subplots(len(shown), 1, figsize=(WIDTH, 0.85 * len(shown) + 0.6), sharex=True, squeeze=False)
    thinned = False
    for ax, p in zip(axes[:, 0], shown):
        changes = thin(p["changes"], end)
        thinned = thinned or len(changes) < len(p["changes"])
        t = [c[0] for c in changes] + [end]
        n = [c[1] for c in changes]
        n.append(n[-1])
        ax.step(t, n, where="post", color=TOKENS, linewidth=1.2)
        ax.fill_between(t, n, step="post", color=TOKENS, alpha=0.15, linewidth=0)
        ax.set_ylabel(short(p["name"], 22), rotation=0, ha="right", va="center")
        top = max(n)
        ax.set_ylim(0, max(1, top) * 1.15)
        ax.yaxis.set_major_locator(matplotlib.ticker.MaxNLocator(3, integer=True))
    axes[-1, 0].set_xlabel("time (s)")
    axes[-1, 0].set_xlim(0, end if end > 0 else 1)
    note = ""
    if len(places) > len(shown):
        note = f" The {len(shown)} busiest of the {len(places)} places whose tokens changed."
    if thinned:
        note += f" Places with more than {MAX_POINTS} changes show each window's lowest and highest count."
    return svg(fig), note


def gantt_plot(run):
    tl = run["timeline"]
    names = tl["transitions"]
    end = run["time"]
    occ = tl["occurrences"]
    if not occ:
        return None, "No transition occurred."
    counts = {}
    for o in occ:
        counts[o[0]] = counts.get(o[0], 0) + 1
    rows = sorted(counts, key=lambda t: -counts[t])[:MAX_ROWS]
    rows.sort()
    row_of = {t: i for i, t in enumerate(rows)}
    fig, ax = plt.subplots(figsize=(WIDTH, 0.32 * len(rows) + 0.9))
    tick = max(end, run["dt"]) / 800  # an occurrence of no duration still shows
    # occurrences of one transition that overlap (it has servers) go to lanes of its row: each
    # to the first lane free when it starts (they come in the order they started)
    bars = {t: [] for t in rows}
    lane_ends = {t: [] for t in rows}
    drawn = 0
    for t, s, e in occ:
        if t not in row_of or drawn >= MAX_BARS:
            continue
        stop = end if e is None else e
        width = max(stop - s, tick)
        ends = lane_ends[t]
        lane = next((i for i, x in enumerate(ends) if x <= s), None)
        if lane is None and len(ends) < MAX_LANES:
            ends.append(s)
            lane = len(ends) - 1
        if lane is None:  # more at once than lanes: the one that frees first
            lane = min(range(len(ends)), key=ends.__getitem__)
        ends[lane] = max(ends[lane], s + width)
        bars[t].append((s, width, lane))
        drawn += 1
    for t in rows:
        lanes = max(1, len(lane_ends[t]))
        height = 0.7 / lanes
        for lane in range(lanes):
            spans = [(s, w) for s, w, k in bars[t] if k == lane]
            top = row_of[t] - 0.35 + lane * height
            ax.broken_barh(spans, (top + 0.04 * height if lanes > 1 else top, height * (0.92 if lanes > 1 else 1)),
                           facecolors=GANTT, edgecolor="none")
    ax.set_yticks(range(len(rows)), [short(names[t], 30) for t in rows])
    ax.set_ylim(len(rows) - 0.5, -0.5)
    ax.set_xlim(0, end if end > 0 else 1)
    ax.set_xlabel("time (s)")
    ax.grid(axis="y", visible=False)
    notes = []
    if len(counts) > len(rows):
        notes.append(f"The {len(rows)} transitions that occurred most of the {len(counts)} that occurred.")
    if drawn < sum(counts[t] for t in rows):
        notes.append(f"The first {MAX_BARS:,} occurrences.")
    return svg(fig), " ".join(notes)


def throughput_plot(run):
    tl = run["timeline"]
    names = tl["transitions"]
    end = run["time"]
    done = {}
    for t, s, e in tl["occurrences"]:
        if e is not None:
            done.setdefault(t, []).append(e)
    if not done or end <= 0:
        return None, "No occurrence completed."
    series = sorted(done, key=lambda t: (-len(done[t]), t))[:MAX_SERIES]
    fig, ax = plt.subplots(figsize=(WIDTH, 3.2))
    for k, t in enumerate(series):
        ends = sorted(done[t])
        rate = 60.0 * len(ends) / end
        ax.step([0.0] + ends + [end], [0] + list(range(1, len(ends) + 1)) + [len(ends)], where="post",
                color=THROUGHPUT[k], linewidth=1.4, label=f"{short(names[t], 34)}  ({number(rate, 3)} per min)")
    ax.set_xlim(0, end)
    ax.set_ylim(bottom=0)
    ax.yaxis.set_major_locator(matplotlib.ticker.MaxNLocator(integer=True))
    ax.set_xlabel("time (s)")
    ax.set_ylabel("completions so far")
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)
    note = "The slope is the throughput; the legend gives each transition's mean over the run."
    if len(done) > len(series):
        note += f" The {len(series)} transitions that completed most of the {len(done)} that completed."
    return svg(fig), note


def cycles_plot(run):
    cycles = [c for c in run["cycles"] if not c["flow"] and c["bound"] is not None]
    if not cycles:
        return None, "The net has no timed cycle with a bound."
    bars = []
    for c in cycles[:MAX_CYCLES]:
        bars.append((short(c["invariant"].replace(" + " + PREFIX, " + "), 50), c["bound"], c["measured"]))
        for k in c.get("circuits", [])[:4]:
            path = " → ".join(short(t, 60) for t in k["transitions"])
            bars.append(("via " + short(path, 46), k["bound"], k["measured"]))
    fig, ax = plt.subplots(figsize=(WIDTH, 0.42 * len(bars) + 1.0))
    labelled = set()
    for i, (label, bound, measured) in enumerate(bars):
        ax.barh(i - 0.18, bound, height=0.34, color=BOUND, label=None if "b" in labelled else "bound")
        labelled.add("b")
        if measured:
            ax.barh(i + 0.18, measured, height=0.34, color=MEASURED, label=None if "m" in labelled else "measured")
            labelled.add("m")
    ax.set_yticks(range(len(bars)), [b[0] for b in bars])
    ax.set_ylim(len(bars) - 0.5, -0.6)
    ax.set_xlabel("cycle time (s)")
    ax.grid(axis="y", visible=False)
    ax.legend(loc="lower left", bbox_to_anchor=(0.0, 1.0), ncols=2, frameon=False)
    note = ""
    if len(cycles) > MAX_CYCLES:
        note = f"The {MAX_CYCLES} cycles with the largest bounds of {len(cycles)}."
    return svg(fig), note


def levels_plot(run):
    """Each continuous place's amount over the run, titled with the place and its unit."""
    lv = run.get("levels")
    if not lv or not lv["places"]:
        return None, ""
    shown = lv["places"][:MAX_PLACES]
    time = lv["time"]
    fig, axes = plt.subplots(len(shown), 1, figsize=(WIDTH, 1.6 * len(shown) + 0.6), sharex=True, squeeze=False)
    thinned = False
    for ax, p in zip(axes[:, 0], shown):
        pts = [(t, v) for t, v in zip(time, p["values"]) if v is not None]
        thinned = thinned or len(pts) > MAX_POINTS
        pts = thin(pts, run["time"])
        t = [q[0] for q in pts]
        v = [q[1] for q in pts]
        ax.plot(t, v, color=LEVELS, linewidth=1.4)
        ax.fill_between(t, v, color=LEVELS, alpha=0.15, linewidth=0)
        unit = f" ({p['unit']})" if p["unit"] else ""
        ax.set_title(f"{short(p['name'], 60)}{unit}", loc="left", fontsize=10)
        top = max(v) if v else 0
        cap = p.get("capacity")
        if cap is not None and cap <= 2 * max(top, 1e-12):
            # the capacity drawn when the amount came near it
            ax.axhline(cap, color=BOUND, linestyle="--", linewidth=1)
            ax.annotate(f"capacity {number(cap)}", (1.0, cap), xycoords=("axes fraction", "data"),
                        xytext=(-4, 3), textcoords="offset points", ha="right", va="bottom", fontsize=8,
                        color="#666")
            top = max(top, cap)
        ax.set_ylim(0, top * 1.12 if top > 0 else 1)
        ax.yaxis.set_major_locator(matplotlib.ticker.MaxNLocator(4))
        ax.grid(axis="y", color="#e5e5e5", linewidth=0.6)
    axes[-1, 0].set_xlabel("time (s)")
    axes[-1, 0].set_xlim(0, run["time"] if run["time"] > 0 else 1)
    fig.tight_layout()
    note = f"The first {MAX_PLACES} of {len(lv['places'])} continuous places." if len(lv["places"]) > MAX_PLACES else ""
    if thinned:
        note += f" Levels of more than {MAX_POINTS} steps show each window's lowest and highest amount."
    return svg(fig), note.strip()


def signals_plot(run):
    sig = run.get("signals")
    if not sig or not sig["columns"]:
        return None, ""
    # a position's three columns (name.x, name.y, name.z) share a plot
    groups = []
    for i, col in enumerate(sig["columns"]):
        m = re.fullmatch(r"(.*)\.([xyz])", col)
        key = m.group(1) if m else col
        if groups and groups[-1][0] == key and m:
            groups[-1][1].append(i)
        else:
            groups.append((key, [i]))
    shown = groups[:MAX_SIGNALS]
    time = sig["time"]
    fig, axes = plt.subplots(len(shown), 1, figsize=(WIDTH, 1.25 * len(shown) + 0.6), sharex=True, squeeze=False)
    for ax, (key, cols) in zip(axes[:, 0], shown):
        for k, c in enumerate(cols):
            pts = [(t, v) for t, v in zip(time, sig["values"][c]) if v is not None]
            if not pts:
                continue
            label = sig["columns"][c][len(key) + 1:] if len(cols) > 1 else None
            ax.plot([p[0] for p in pts], [p[1] for p in pts], color=SIGNALS[k % 3], linewidth=1.3, label=label)
        ax.set_ylabel(short(key, 22), rotation=0, ha="right", va="center")
        if len(cols) > 1:
            ax.legend(loc="upper left", bbox_to_anchor=(1.0, 1.0), frameon=False)
    axes[-1, 0].set_xlabel("time (s)")
    axes[-1, 0].set_xlim(0, run["time"] if run["time"] > 0 else 1)
    note = f"The first {MAX_SIGNALS} of {len(groups)} signals." if len(groups) > MAX_SIGNALS else ""
    return svg(fig), note


CSS = """
body { font-family: "DejaVu Sans", system-ui, sans-serif; color: #222; margin: 0; background: #fafafa; }
main { max-width: 1120px; margin: 0 auto; padding: 24px 32px 48px; background: #fff; }
h1 { font-size: 22px; margin: 0 0 4px; }
h2 { font-size: 17px; margin: 28px 0 6px; border-bottom: 1px solid #ddd; padding-bottom: 3px; }
.run { color: #555; margin: 0 0 12px; }
.caption, .note { color: #555; font-size: 13px; margin: 4px 0 8px; overflow-wrap: anywhere; }
.wide { overflow-x: auto; }
table { border-collapse: collapse; font-size: 13px; margin: 6px 0; }
th, td { padding: 3px 10px; border-bottom: 1px solid #eee; text-align: left; vertical-align: top; }
th { background: #f3f3f3; font-weight: 600; }
.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
svg { max-width: 100%; height: auto; display: block; }
nav a { margin-right: 14px; font-size: 13px; }
.error { color: #b00020; white-space: pre-wrap; font-family: monospace; font-size: 12px; }
"""


def page(text):
    global PREFIX
    run = json.loads(text)
    style()
    PREFIX = common_prefix(run["timeline"]["transitions"] + [p["name"] for p in run["timeline"]["places"]])
    body = []
    stopped = run["stopped"]
    title = run["model"]
    body.append(f"<h1>{esc(title)}</h1>")
    body.append(f'<p class="run">seed {esc(run["seed"])} · {number(run["time"])} s in {number(run["steps"])} steps '
                f'of {number(run["dt"])} s · stopped: {esc(stopped)}</p>')
    if run.get("message"):
        body.append(f'<p class="error">{esc(run["message"])}</p>')
    sections = []
    if run.get("param_table"):
        params = run["param_table"]
        if all(p["value"] == p["declared"] for p in params):
            rows = [(p["name"], number(p["value"]), p["unit"]) for p in params]
            tab = table(["parameter", "value", "unit"], rows, [False, True, False])
        else:
            rows = [(p["name"], number(p["value"]), p["unit"], number(p["declared"])) for p in params]
            tab = table(["parameter", "value", "unit", "declared in the model"], rows, [False, True, False, True])
        sections.append(("parameters", "Parameters", tab, ""))
    if run.get("figures") or run.get("figures_error"):
        units = run.get("figure_units", {})
        rows = [(k, v if isinstance(v, str) else number(v), units.get(k, "")) for k, v in run["figures"].items()]
        body_ = table(["figure", "value", "unit"], rows, [False, True, False])
        if run.get("figures_error"):
            body_ += f'<p class="error">{esc(run["figures_error"])}</p>'
        sections.append(("figures", "The model's figures", body_, "What the model's summary() returns."))
    plots = [
        ("levels", "Levels over time", levels_plot,
         "Each continuous place's amount after every step (dashed: its capacity)."),
        ("tokens", "Tokens over time", tokens_plot, "Each place's tokens (all its slots) over the run."),
        ("gantt", "Transition occurrences", gantt_plot, "Each bar is one occurrence, from its start to its completion; occurrences of one transition "
         "that overlap (it has servers) share its row in lanes."),
        ("throughput", "Throughput over time", throughput_plot, "Occurrences completed since the start."),
        ("cycles", "Cycle times and their bounds", cycles_plot,
         "Each cycle of the net (a P-invariant carrying tokens): the bound from its durations (grey) beside "
         "the slowest mean cycle measured among its transitions (red); a token with alternative circuits "
         "shows each circuit it took."),
        ("signals", "Signals", signals_plot, "What the model's signals section (and --signal) recorded."),
    ]
    tl = run["timeline"]
    cut = ""
    if tl.get("cut_at") is not None:
        cut = (f" Occurrences and tokens are recorded up to t = {number(tl['cut_at'])} s; "
               f"{number(tl['dropped'])} later records were not kept.")
    if PREFIX:
        body.append(f'<p class="note">The plots name places and transitions below {esc(PREFIX)}.</p>')
    for anchor, title_, draw, caption in plots:
        picture, note = draw(run)
        if picture is None and not note:
            continue
        content = picture or ""
        if note:
            content += f'<p class="note">{esc(note)}</p>'
        if anchor in ("tokens", "gantt", "throughput") and cut:
            content += f'<p class="note">{esc(cut)}</p>'
        sections.append((anchor, title_, content, esc(caption)))
    # with servers: the occurrences at once, averaged, beside the share of servers busy
    servers = any("servers" in t for t in run["transitions"])
    rows = [(t["name"], t["occurrences"], number(t["mean_cycle"]) if t["cycles"] else "–",
             number(t["min_cycle"]) if t["cycles"] else "–", number(t["max_cycle"]) if t["cycles"] else "–",
             "–" if t["utilisation"] is None else f"{100 * t['utilisation']:.1f} %")
            + ((f"{t.get('mean_busy', t['utilisation']):.2f}", str(t.get("servers", 1))) if servers else ())
            for t in run["transitions"] if not t.get("continuous")]
    if rows:
        head = ["transition", "occurrences", "mean cycle (s)", "min (s)", "max (s)", "busy"]
        sections.append(("transitions", "Transitions",
                         table(head + (["at once", "servers"] if servers else []),
                               [tuple(number(c) if isinstance(c, int) else c for c in r) for r in rows],
                               [False] + [True] * (len(head) - 1 + (2 if servers else 0))), ""))
    rows = [(p["name"] + (" (sensor)" if p["sensors_only"] else ""), number(p["mean_tokens"]),
             number(p["max_tokens"]), number(p["final_tokens"]), number(p["throughput"]))
            for p in run["places"] if not p.get("continuous")]
    if rows:
        sections.append(("places", "Places",
                         table(["place", "mean tokens", "max", "final", "deposits per s"], rows,
                               [False, True, True, True, True]), ""))
    if run.get("amounts"):
        rows = [(a["name"], a["unit"], number(a["final"]), number(a["lowest"]), number(a["highest"]), number(a["mean"]))
                for a in run["amounts"]]
        sections.append(("amounts", "Continuous places",
                         table(["place", "unit", "final", "lowest", "highest", "mean"], rows,
                               [False, False, True, True, True, True]), "Amounts over the run; the mean is weighted by time."))
    if run.get("flows"):
        rows = [(f["name"], number(f["moved"]), f["unit"], f"{100 * f['flowing']:.1f} %") for f in run["flows"]]
        sections.append(("flows", "Continuous transitions",
                         table(["transition", "moved", "unit", "flowing"], rows, [False, True, False, True]),
                         "What each flow moved (its rate over time; an arc moves its weight times this), and "
                         "the share of the run it flowed."))
    if run["cycles"]:
        rows = [(c["invariant"], number(c["tokens"]), "flow" if c["flow"] else number(c["bound"]),
                 "–" if c["flow"] or not c["measured"] else number(c["measured"])) for c in run["cycles"]]
        note = "" if run.get("cycles_complete", True) else " The cycle bounds were cut short by their time budget."
        sections.append(("cycle-table", "Cycles",
                         table(["cycle (P-invariant)", "tokens", "bound (s)", "measured (s)"], rows,
                               [False, True, True, True], note=note), ""))
    nav = " ".join(f'<a href="#{a}">{esc(t)}</a>' for a, t, _, _ in sections)
    body.append(f"<nav>{nav}</nav>")
    for anchor, title_, content, caption in sections:
        body.append(section(anchor, title_, content, caption))
    return ("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
            f"<title>{esc(title)} — gdpn report</title><style>{CSS}</style></head>"
            f"<body><main>{''.join(body)}</main></body></html>\n")
