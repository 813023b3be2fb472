"""The factory's HTML report as a browser shows it.

Runs `gdpn run examples/factory --html`, opens the page in headless Chromium (Debian's),
takes a screenshot, and checks that every plot is drawn: each kind of plot has its own
colour (src/experiments/python/report_page.py), so the screenshot must hold each colour,
in bands from top to bottom in the page's order (tokens, occurrences, throughput, cycles,
signals), and the page's text must name what it shows.

usage: html_report_check.py GDPN MODEL WORKDIR
"""

import os
import subprocess
import sys

import matplotlib.image
import numpy

GDPN, MODEL, WORK = sys.argv[1:4]
os.makedirs(WORK, exist_ok=True)
page = os.path.join(WORK, "factory.html")
shot = os.path.join(WORK, "factory.png")
for f in (page, shot):
    if os.path.exists(f):
        os.remove(f)

run = subprocess.run([GDPN, "run", MODEL, "--quiet", "--html", page], capture_output=True, text=True)
assert run.returncode == 0, run.stderr
text = open(page, encoding="utf-8").read()
assert text.count("<svg") == 5, text.count("<svg")
for heading in ("Tokens over time", "Transition occurrences", "Throughput over time",
                "Cycle times and their bounds", "Signals", "share of those painted", "47.62"):
    assert heading in text, heading
for loads in ('src="http', 'href="http', "url(http", "@import", "<script", "<link"):
    assert loads not in text, f"the page loads something from elsewhere: {loads}"

browser = subprocess.run(
    ["chromium", "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars", "--force-device-scale-factor=1",
     f"--screenshot={shot}", "--window-size=1200,4400", "file://" + os.path.abspath(page)],
    capture_output=True, text=True, timeout=120)
assert os.path.exists(shot), browser.stderr[-2000:]
pixels = (matplotlib.image.imread(shot)[:, :, :3] * 255).round().astype(int)
assert pixels.shape[1] == 1200, pixels.shape


def rows_with(colour, tolerance=8, least=2000, run=8):
    """The rows of the screenshot that hold `colour` (#rrggbb) in a horizontal run of `run`
    pixels (a line or a bar, not the edge of a letter); at least `least` such pixels in all."""
    rgb = numpy.array([int(colour[i:i + 2], 16) for i in (1, 3, 5)])
    hit = (numpy.abs(pixels - rgb) <= tolerance).all(axis=2)
    runs = hit.copy()
    for k in range(1, run):  # a pixel that starts a run of `run` hits
        runs[:, :-k] &= hit[:, k:]
        runs[:, -k:] = False
    assert runs.sum() * run >= least, f"{colour}: {runs.sum()} runs of {run} pixels (a plot is missing)"
    return numpy.nonzero(runs.any(axis=1))[0]


tokens = rows_with("#1f77b4")
gantt = rows_with("#ff7f0e")
bound = rows_with("#9a9a9a")
measured = rows_with("#d62728")
signals = rows_with("#9467bd", least=500)
throughput = rows_with("#2ca02c", least=300)  # the busiest transition's line
# the plots follow each other down the page: each starts below where the one before started
starts = [tokens.min(), gantt.min(), throughput.min(), min(bound.min(), measured.min()), signals.min()]
assert starts == sorted(starts), starts
# the Gantt chart lies below the token plots' top and above the cycle plot
assert gantt.min() > tokens.min() and numpy.median(gantt) < measured.min(), (gantt.min(), measured.min())
print("html report: 5 plots in order at rows", [int(s) for s in starts])
