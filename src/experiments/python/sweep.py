"""Sweeps: every combination of parameter values, each replicated over seeds, run on Dask.

Each run is `gdpn run MODEL --quiet --seed S --until T --param NAME=VALUE ... --report R`
in a process of its own, so that a run that fails (a script error, a crash) is reported
with its parameters and does not take a worker, or the other runs, with it. A worker needs
the gdpn program and the model at the same paths as the machine that starts the sweep.

The table holds one row per run, in the order of the combinations and then the seeds,
whatever the number of workers and whichever finished first; each combination runs the
same seeds (common random numbers). The summary gives per combination the mean and a 95 %
confidence interval (Student's t) of every numeric figure.

gdpn calls main(text) for `gdpn sweep`; the Python module gives sweep().
"""

import csv
import io
import itertools
import json
import math
import os
import subprocess
import sys
import tempfile

# Student's t at 0.975 for 1 to 30 degrees of freedom
_T975 = [12.7062047, 4.3026527, 3.1824463, 2.7764451, 2.5705818, 2.4469119, 2.3646243, 2.3060041,
         2.2621572, 2.2281389, 2.2009852, 2.1788128, 2.1603687, 2.1447867, 2.1314495, 2.1199053,
         2.1098156, 2.1009220, 2.0930241, 2.0859634, 2.0796138, 2.0738731, 2.0686576, 2.0638986,
         2.0595386, 2.0555294, 2.0518305, 2.0484071, 2.0452296, 2.0422725]


def t975(df):
    """Student's t quantile at 0.975 for `df` degrees of freedom (a table to 30, then the
    Cornish-Fisher expansion, within 1e-5)."""
    if df <= 30:
        return _T975[df - 1]
    z = 1.959963984540054
    return (z + (z ** 3 + z) / (4 * df) + (5 * z ** 5 + 16 * z ** 3 + 3 * z) / (96 * df ** 2)
            + (3 * z ** 7 + 19 * z ** 5 + 17 * z ** 3 - 15 * z) / (384 * df ** 3))


class SweepError(ValueError):
    """A sweep asked for something it cannot do; the message says what."""


def _number(text, where):
    try:
        value = float(text)
    except ValueError:
        raise SweepError(f"{where}: expected a number, got '{text}'") from None
    if not math.isfinite(value):
        raise SweepError(f"{where}: expected a finite number, got '{text}'")
    return value


def _format(value):
    """A value as --param takes it: whole numbers without a point, others as their shortest
    exact decimal."""
    if float(value).is_integer() and abs(value) < 2 ** 53:
        return str(int(value))
    return repr(float(value))


def parse_values(name, spec):
    """The values of a --param NAME=SPEC: a comma-separated list of numbers and ranges
    FROM..TO (step 1) or FROM..TO:STEP, TO included when a step lands on it."""
    where = f"--param {name}={spec}"
    values = []
    for item in str(spec).split(","):
        item = item.strip()
        if not item:
            raise SweepError(f"{where}: an empty value")
        if ".." in item:
            lo, _, rest = item.partition("..")
            hi, _, step = rest.partition(":")
            lo, hi = _number(lo, where), _number(hi, where)
            step = _number(step, where) if step else 1.0
            if step <= 0:
                raise SweepError(f"{where}: the step must be positive, got {_format(step)}")
            if hi < lo:
                raise SweepError(f"{where}: the range ends ({_format(hi)}) before it starts ({_format(lo)})")
            span = (hi - lo) / step
            if not math.isfinite(span) or span > 10000:
                raise SweepError(f"{where}: more than 10000 values")
            count = math.floor(span * (1 + 1e-12) + 1e-9) + 1
            # each value from its index, rounded to 12 digits: 0.1 steps give 0.3, not 0.30000000000000004
            values += [float(f"{lo + k * step:.12g}") for k in range(count)]
        else:
            values.append(_number(item, where))
    # a value given twice would count its runs twice (and narrow its interval): once each
    return list(dict.fromkeys(values))


def combinations(params):
    """Every combination of the parameters' values, the first parameter varying slowest."""
    names = list(params)
    return [dict(zip(names, combo)) for combo in itertools.product(*(params[n] for n in names))]


def run_one(gdpn, model, values, seed, until, timeout):
    """One run in a process of its own: its figures, or its error. Runs on a worker."""
    with tempfile.TemporaryDirectory(prefix="gdpn-sweep-") as folder:
        report = os.path.join(folder, "report.json")
        command = [gdpn, "run", model, "--quiet", "--seed", str(seed), "--report", report]
        if until is not None:
            command += ["--until", repr(float(until))]
        for name, value in values.items():
            command += ["--param", f"{name}={_format(value)}"]
        try:
            done = subprocess.run(command, capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return {"error": f"ran longer than {timeout} s"}
        except OSError as e:
            return {"error": f"could not start {gdpn}: {e.strerror}"}
        if done.returncode != 0 or not os.path.exists(report):
            lines = [line for line in done.stderr.splitlines() if line.strip()]
            why = " / ".join(lines[-3:]) if lines else f"exit status {done.returncode}"
            return {"error": why}
        with open(report, encoding="utf-8") as f:
            r = json.load(f)
    if r.get("figures_error"):
        lines = [line.strip() for line in r["figures_error"].splitlines() if line.strip()]
        return {"error": "summary(): " + (lines[0] if lines else "failed")}
    figures = {"stopped": r["stopped"], "time": r["time"]}
    units = {}
    # a figure named like a column of the table (a parameter, seed, error, stopped, time)
    # keeps its place under "summary.NAME"
    reserved = set(values) | {"seed", "error", "stopped", "time"}
    for name, value in r.get("figures", {}).items():
        key = "summary." + name if name in reserved else name
        figures[key] = value
        if name in r.get("figure_units", {}):
            units[key] = r["figure_units"][name]
    return {"figures": figures, "units": units}


def _progress(done, total, failed, stream):
    width = 30
    filled = width * done // total
    tail = f", {failed} failed" if failed else ""
    stream.write(f"\r[{'#' * filled}{'.' * (width - filled)}] {done}/{total} runs{tail}")
    if done == total:
        stream.write("\n")
    stream.flush()


def execute(tasks, workers=None, scheduler=None, progress=False):
    """Runs every task (the arguments of run_one) and returns their results in task order:
    serially in this process with workers=0, else on Dask (a cluster at `scheduler`, or a
    local one of `workers` threads, each task a process of its own; all cores by default)."""
    results = [None] * len(tasks)
    failed = 0
    stream = sys.stderr
    if workers == 0 and scheduler is None:
        for i, task in enumerate(tasks):
            results[i] = run_one(*task)
            failed += "error" in results[i]
            if progress:
                _progress(i + 1, len(tasks), failed, stream)
        return results
    import logging
    from distributed import Client, LocalCluster, as_completed

    # the cluster's own chatter (ports, start-up) is not the user's business
    for name in ("distributed", "tornado"):
        logging.getLogger(name).setLevel(logging.ERROR)
    cluster = None
    if scheduler is None:
        cluster = LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1, processes=False,
                               dashboard_address=None)
        client = Client(cluster)
    else:
        try:
            client = Client(scheduler, timeout="10s")
        except (OSError, TimeoutError) as e:
            raise SweepError(f"--scheduler {scheduler}: no Dask scheduler answers there ({e})") from None
        except (ValueError, TypeError) as e:
            raise SweepError(f"--scheduler {scheduler}: expected an address like tcp://HOST:PORT ({e})") from None
    try:
        # keys of this sweep alone: sweeps sharing a scheduler must not share results
        import uuid
        token = uuid.uuid4().hex
        futures = [client.submit(run_one, *task, key=f"gdpn-run-{token}-{i}", pure=False)
                   for i, task in enumerate(tasks)]
        index = {f.key: i for i, f in enumerate(futures)}
        done = 0
        for future in as_completed(futures):
            i = index[future.key]
            try:
                results[i] = future.result()
            except Exception as e:  # the worker itself failed (it died, or could not run the task)
                results[i] = {"error": f"{type(e).__name__}: {e}"}
            done += 1
            failed += "error" in results[i]
            if progress:
                _progress(done, len(tasks), failed, stream)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    return results


def _mean_ci(xs):
    n = len(xs)
    mean = math.fsum(xs) / n
    if n < 2:
        return mean, None, None
    var = math.fsum((x - mean) ** 2 for x in xs) / (n - 1)
    half = t975(n - 1) * math.sqrt(var / n)
    return mean, mean - half, mean + half


class Sweep:
    """What a sweep gave: `rows` (one dict per run: the parameters, seed, every figure, and
    `error` for a failed run), `figures` (their names, in order), `units`, and per combination
    the mean and 95 % confidence interval of each numeric figure (summary())."""

    def __init__(self, params, rows, figures, units, param_units=None):
        self.params = params      # name -> list of values
        self.rows = rows
        self.figures = figures
        self.units = units        # figure -> unit
        self.param_units = param_units or {}

    @property
    def failed(self):
        """The runs that failed: their rows (parameters, seed, error)."""
        return [r for r in self.rows if r.get("error")]

    def numeric(self):
        """The figures that are numbers in every run that gave them."""
        out = []
        for f in self.figures:
            vals = [r[f] for r in self.rows if f in r and r[f] is not None and not r.get("error")]
            if vals and all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in vals):
                out.append(f)
        return out

    def summary_rows(self):
        """Per combination: its values, the runs, the failed runs, and for each numeric
        figure its mean, low and high (95 % confidence interval)."""
        names = list(self.params)
        groups = {}
        for r in self.rows:
            groups.setdefault(tuple(r[n] for n in names), []).append(r)
        out = []
        numeric = self.numeric()
        for key, rows in groups.items():
            good = [r for r in rows if not r.get("error")]
            row = dict(zip(names, key))
            row["runs"] = len(good)
            row["failed"] = len(rows) - len(good)
            for f in numeric:
                xs = [float(r[f]) for r in good if r.get(f) is not None]
                mean, lo, hi = _mean_ci(xs) if xs else (None, None, None)
                row[f] = mean
                row[f + " low"] = lo
                row[f + " high"] = hi
            out.append(row)
        return out

    def run_columns(self):
        """The columns of runs_csv(): the parameters, seed, every figure, error."""
        return list(self.params) + ["seed"] + self.figures + ["error"]

    def summary_columns(self):
        """The columns of summary_csv(): the parameters, runs, failed, and each numeric figure
        with its interval (`FIGURE low`, `FIGURE high`)."""
        cols = list(self.params) + ["runs", "failed"]
        for f in self.numeric():
            cols += [f, f + " low", f + " high"]
        return cols

    def runs_csv(self):
        """The runs as CSV text, one row a run (what `gdpn sweep -o` writes)."""
        return _csv(self.run_columns(), self.rows)

    def summary_csv(self):
        """The summary as CSV text, one row a combination (what `gdpn sweep --summary` writes)."""
        return _csv(self.summary_columns(), self.summary_rows())

    @property
    def runs(self):
        """The runs as a pandas DataFrame: parameters, seed, every figure, error."""
        import pandas
        return pandas.DataFrame(self.rows, columns=self.run_columns())

    @property
    def summary(self):
        """Per combination, as a pandas DataFrame: runs, failed runs, and each numeric figure's
        mean with its 95 % confidence interval (columns `FIGURE low` and `FIGURE high`)."""
        import pandas
        return pandas.DataFrame(self.summary_rows(), columns=self.summary_columns())

    def __repr__(self):
        return f"<gdpn sweep: {len(self.rows)} runs, {len(self.failed)} failed>\n" + _table(self)

    def check_against(self, against):
        """Raises SweepError unless `against` (or the first parameter) can be plotted against."""
        names = list(self.params)
        if not names:
            raise SweepError("--plot: the sweep varies no parameter")
        if against and against not in names:
            raise SweepError(f"--against: '{against}' is not a swept parameter ({', '.join(names)})")

    def plot(self, figure, against=None, path=None):
        """`figure`'s mean against parameter `against` (the first by default), a line per
        combination of the other parameters, with the 95 % intervals as bars. Saves to `path`
        (SVG, PNG or PDF by its name) when given; returns the matplotlib figure."""
        import matplotlib
        ext = os.path.splitext(str(path))[1].lower() if path is not None else ""
        if path is not None:
            matplotlib.use("svg" if ext == ".svg" else "pdf" if ext == ".pdf" else "Agg")
        import matplotlib.pyplot as plt
        plt.rcParams["svg.hashsalt"] = "gdpn"  # the same sweep, the same file
        if figure not in self.numeric():
            known = ", ".join(self.numeric()) or "none"
            raise SweepError(f"--plot: no numeric figure '{figure}' (there are: {known})")
        names = list(self.params)
        if not names:
            raise SweepError("--plot: the sweep varies no parameter")
        against = against or names[0]
        if against not in names:
            raise SweepError(f"--against: '{against}' is not a swept parameter ({', '.join(names)})")
        others = [n for n in names if n != against]
        lines = {}
        for row in self.summary_rows():
            lines.setdefault(tuple(row[n] for n in others), []).append(row)
        fig, ax = plt.subplots(figsize=(7.5, 4.2))
        for key, rows in lines.items():
            rows.sort(key=lambda r: r[against])
            xs = [r[against] for r in rows if r[figure] is not None]
            ys = [r[figure] for r in rows if r[figure] is not None]
            lo = [r[figure] - r[figure + " low"] if r[figure + " low"] is not None else 0
                  for r in rows if r[figure] is not None]
            hi = [r[figure + " high"] - r[figure] if r[figure + " high"] is not None else 0
                  for r in rows if r[figure] is not None]
            label = ", ".join(f"{n} = {_format(v)}" for n, v in zip(others, key)) or None
            ax.errorbar(xs, ys, yerr=[lo, hi], marker="o", capsize=3, linewidth=1.4, label=label)
        unit = self.units.get(figure, "")
        ax.set_xlabel(against + (f" ({self.param_units.get(against)})" if self.param_units.get(against) else ""))
        ax.set_ylabel(figure + (f" ({unit})" if unit else ""))
        seeds = max((r["runs"] for r in self.summary_rows()), default=0)
        ax.set_title(f"mean of {seeds} runs each, with its 95 % confidence interval", fontsize=10)
        ax.grid(True, color="#e6e6e6")
        if others:
            ax.legend(frameon=False, fontsize=8)
        if path is not None:
            metadata = {"Date": None} if ext == ".svg" else {"CreationDate": None} if ext == ".pdf" else None
            fig.savefig(path, bbox_inches="tight", metadata=metadata, format=ext[1:] or None)
        return fig


def _csv(columns, rows):
    out = io.StringIO()
    w = csv.writer(out, lineterminator="\n")
    w.writerow(columns)
    for r in rows:
        w.writerow(["" if r.get(c) is None else (repr(r[c]) if isinstance(r[c], float) else r[c]) for c in columns])
    return out.getvalue()


def _check(gdpn, model, values):
    """Checks the model with each parameter at each of its values before any run, so that a
    misspelt name or a value the parameter refuses (a decimal for a whole number) is one
    error, not a failure of every run. What the model makes of a value (a negative duration)
    stays the failure of the runs with it."""
    if not values:
        return
    for k in range(max(len(v) for v in values.values())):
        command = [gdpn, "check", model]
        for name, vs in values.items():
            command += ["--param", f"{name}={_format(vs[min(k, len(vs) - 1)])}"]
        try:
            done = subprocess.run(command, capture_output=True, text=True, timeout=600)
        except (OSError, subprocess.TimeoutExpired) as e:
            raise SweepError(f"{gdpn} check {model}: {e}") from None
        refused = [line for line in done.stderr.splitlines() if line.startswith("--param: error:")]
        if done.returncode != 0 and refused:
            raise SweepError(refused[0])


def run_sweep(gdpn, model, params, seeds=1, seed=1, until=None, workers=None, scheduler=None, progress=False,
              timeout=None, param_units=None):
    """Runs the sweep and returns a Sweep. `params`: name -> list of numbers or a SPEC text
    (parse_values); `seeds` replications with seeds seed, seed + 1, ..."""
    values = {}
    for name, spec in params.items():
        if isinstance(spec, (list, tuple)):
            values[name] = list(dict.fromkeys(_number(v, f"params[{name!r}]") for v in spec))
        else:
            values[name] = parse_values(name, spec)
        if not values[name]:
            raise SweepError(f"--param {name}: no values")
    if not isinstance(seeds, int) or seeds < 1:
        raise SweepError(f"--seeds: a whole number of runs per combination, at least 1, got {seeds!r}")
    if workers is not None and (not isinstance(workers, int) or workers < 0):
        raise SweepError(f"--workers: a whole number, 0 or more, got {workers!r}")
    if until is not None and not (isinstance(until, (int, float)) and math.isfinite(until) and until >= 0):
        raise SweepError(f"--until: a time of at least 0 seconds, got {until!r}")
    if not os.path.exists(model):
        raise SweepError(f"{model}: no such model file or folder")
    model = os.path.abspath(model)
    _check(gdpn, model, values)
    total = math.prod(len(v) for v in values.values()) * seeds
    if total > 1_000_000:
        raise SweepError(f"{total} runs; at most 1000000 in one sweep")
    combos = combinations(values)
    tasks = [(gdpn, model, combo, seed + k, until, timeout) for combo in combos for k in range(seeds)]
    results = execute(tasks, workers, scheduler, progress)
    rows, figures, units = [], [], {}
    for (g, m, combo, s, u, t), result in zip(tasks, results):
        row = dict(combo)
        row["seed"] = s
        if "error" in result:
            row["error"] = result["error"]
        else:
            for name, value in result["figures"].items():
                if name not in figures:
                    figures.append(name)
                row[name] = value
            units.update(result["units"])
        rows.append(row)
    units.setdefault("time", "s")
    return Sweep(values, rows, figures, units, param_units)


def find_gdpn():
    """The gdpn program the runs use: $GDPN_EXECUTABLE, the one built or installed beside the
    Python module, or the one on the PATH."""
    import shutil
    if os.environ.get("GDPN_EXECUTABLE"):
        return os.environ["GDPN_EXECUTABLE"]
    module = getattr(sys.modules.get("gdpn"), "__file__", None)  # the Python module, when it loaded this
    if module:
        here = os.path.dirname(os.path.abspath(module))
        for candidate in (os.path.join(here, "..", "apps", "gdpn", "gdpn"),  # a build tree
                          os.path.join(here, "..", "..", "..", "bin", "gdpn")):  # PREFIX/lib/python3.X/dist-packages
            if os.access(candidate, os.X_OK):
                return os.path.normpath(candidate)
    found = shutil.which("gdpn")
    if found is None:
        raise SweepError("no gdpn program found: set GDPN_EXECUTABLE, or put gdpn on the PATH")
    return found


def sweep(model, params=None, seeds=1, seed=1, until=None, workers=None, scheduler=None, progress=False,
          timeout=None, gdpn=None):
    """Runs `model` for every combination of `params` (name -> list of numbers, or a text as
    `gdpn sweep --param` takes: "0.4,0.5" or "1..3:0.5"), each with seeds seed, seed + 1, ...
    (`seeds` of them), to `until` seconds: on a local Dask cluster of `workers` (all cores by
    default; 0: one run after another, without Dask), or on the cluster at `scheduler`
    ("tcp://HOST:PORT"). Returns a Sweep: .runs and .summary are pandas DataFrames, .plot()
    draws a figure against a parameter, .failed lists the runs that failed."""
    return run_sweep(gdpn or find_gdpn(), model, dict(params or {}), seeds, seed, until, workers, scheduler,
                     progress, timeout)


def _write(path, text, flag):
    """Writes `text` to `path` as gdpn writes its outputs: beside the target, renamed into
    place when complete; a device, a pipe or a link's target is written through."""
    try:
        if os.path.islink(path) or (os.path.exists(path) and not os.path.isfile(path)):
            with open(path, "w", encoding="utf-8") as f:
                f.write(text)
            return
        folder = os.path.dirname(os.path.abspath(path))
        fd, temporary = tempfile.mkstemp(prefix=".gdpn-", dir=folder)
        try:
            umask = os.umask(0)
            os.umask(umask)
            os.fchmod(fd, 0o666 & ~umask)
            with os.fdopen(fd, "w", encoding="utf-8") as f:
                f.write(text)
            os.replace(temporary, path)
        finally:
            if os.path.exists(temporary):
                os.remove(temporary)
    except OSError as e:
        raise SweepError(f"{flag} {path}: {e.strerror or e}") from None


def _table(sweep, width=100):
    """The summary as text for a terminal: a line per combination, each figure's mean ± the
    half-width of its 95 % interval; a block per combination when that is wider than `width`."""
    numeric = [f for f in sweep.numeric() if f != "time"]
    names = list(sweep.params)

    def label(f):
        return f + (f" ({sweep.units[f]})" if sweep.units.get(f) else "")

    def cell(row, f):
        m, lo, hi = row[f], row[f + " low"], row[f + " high"]
        return "-" if m is None else f"{m:.4g}" + ("" if lo is None else f" ± {(hi - lo) / 2:.2g}")

    def runs(row):
        return str(row["runs"]) + (f" ({row['failed']} failed)" if row["failed"] else "")

    rows = sweep.summary_rows()
    head = names + ["runs"] + [label(f) for f in numeric]
    lines = [[_format(row[n]) for n in names] + [runs(row)] + [cell(row, f) for f in numeric] for row in rows]
    widths = [max([len(h)] + [len(c[i]) for c in lines]) for i, h in enumerate(head)]
    if sum(widths) + 2 * (len(widths) - 1) <= width:
        out = ["  ".join(h.rjust(w) for h, w in zip(head, widths))]
        out += ["  ".join(c.rjust(w) for c, w in zip(cells, widths)) for cells in lines]
        return "\n".join(out) + "\n"
    pad = max([len(label(f)) for f in numeric] + [4])
    out = []
    for row in rows:
        where = ", ".join(f"{n} = {_format(row[n])}" for n in names)
        out.append(f"{where or 'the model as it is'}: {runs(row)} runs")
        out += [f"  {label(f).ljust(pad)}  {cell(row, f)}" for f in numeric]
    return "\n".join(out) + "\n"


def main(text):
    """`gdpn sweep`: the arguments as JSON text; returns the exit status as text."""
    a = json.loads(text)
    # names and figures are UTF-8, as gdpn prints them whatever the locale
    for stream in (sys.stdout, sys.stderr):
        stream.reconfigure(encoding="utf-8")
    try:
        params = {}
        for arg in a["params"]:
            name, eq, spec = arg.partition("=")
            if not eq or not name:
                raise SweepError(f"--param: expects NAME=VALUES, got '{arg}'")
            if name in params:
                raise SweepError(f"--param {name}: given twice")
            params[name] = spec
        for name, spec in params.items():
            parse_values(name, spec)  # mistakes before any run
        for option in ("output", "summary", "plot"):  # and the outputs' folders
            if a.get(option):
                folder = os.path.dirname(os.path.abspath(a[option]))
                if not os.path.isdir(folder) or not os.access(folder, os.W_OK):
                    flag = "-o" if option == "output" else "--" + option
                    raise SweepError(f"{flag} {a[option]}: the folder {folder} is not there or not writable")
        if a.get("plot"):
            if os.path.splitext(a["plot"])[1].lower() not in (".svg", ".png", ".pdf"):
                raise SweepError(f"--plot {a['plot']}: expected a file ending in .svg, .png or .pdf")
            Sweep({n: [] for n in params}, [], [], {}).check_against(a.get("against"))
        sweep = run_sweep(a["gdpn"], a["model"], params, a["seeds"], a["seed"], a.get("until"),
                          a.get("workers"), a.get("scheduler"), a.get("progress", False), a.get("timeout"),
                          a.get("param_units"))
        if a.get("output"):
            _write(a["output"], sweep.runs_csv(), "-o")
        if a.get("summary"):
            _write(a["summary"], sweep.summary_csv(), "--summary")
        if not a.get("quiet"):
            sys.stdout.write(_table(sweep))
        for r in sweep.failed:
            where = ", ".join(f"{n}={_format(r[n])}" for n in sweep.params)
            sys.stderr.write(f"error: run {where + ', ' if where else ''}seed={r['seed']} failed: {r['error']}\n")
        sys.stdout.flush()
        sys.stderr.flush()
        if a.get("plot"):  # last: the runs' failures are said first
            figure = a.get("figure") or next((f for f in sweep.numeric() if f != "time"), None)
            if figure is None:
                raise SweepError("--plot: the runs gave no numeric figure to plot")
            folder = os.path.dirname(os.path.abspath(a["plot"]))
            fd, temporary = tempfile.mkstemp(prefix=".gdpn-", dir=folder, suffix=os.path.splitext(a["plot"])[1])
            os.close(fd)
            try:
                sweep.plot(figure, a.get("against"), temporary)
                os.replace(temporary, a["plot"])
            except OSError as e:
                raise SweepError(f"--plot {a['plot']}: {e.strerror or e}") from None
            finally:
                if os.path.exists(temporary):
                    os.remove(temporary)
        return "1" if sweep.failed else "0"
    except SweepError as e:
        sys.stdout.flush()
        sys.stderr.write(f"error: {e}\n")
        sys.stderr.flush()
        return "2"
    except KeyboardInterrupt:
        sys.stdout.flush()
        sys.stderr.write("error: the sweep was interrupted; no table was written\n")
        sys.stderr.flush()
        return "130"
    except ImportError as e:
        sys.stderr.write(f"error: the sweep needs Python's {e.name or 'module'} (Debian: scripts/install-deps.sh)\n")
        sys.stderr.flush()
        return "1"
