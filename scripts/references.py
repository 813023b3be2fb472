#!/usr/bin/env python3
"""docs/cli.md and docs/python.md, written from the program and the module themselves.

    python3 scripts/references.py --gdpn build/release/apps/gdpn/gdpn --write   # bring them up to date
    python3 scripts/references.py --gdpn build/release/apps/gdpn/gdpn --check   # exit 1 when stale

docs/cli.md is `gdpn reference --format markdown` (the CLI's own option definitions); docs/python.md
is made here from the gdpn module's docstrings (the module found on PYTHONPATH, or beside the
program's build: BUILD/python). --check also runs each command's examples' paths past the
repository (every examples/... path an example names must be there), and holds README.md to
120 lines.
"""

import argparse
import difflib
import inspect
import os
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def cli_reference(gdpn):
    return subprocess.run([gdpn, "reference", "--format", "markdown"], check=True, capture_output=True,
                          text=True).stdout


def signature_and_text(doc):
    """pybind11's docstring: the signature line, then the text."""
    doc = inspect.cleandoc(doc or "")
    first, _, rest = doc.partition("\n")
    return first.strip(), rest.strip()


def python_reference(gdpn):
    out = ["# gdpn: the Python reference", "",
           "Written by `scripts/references.py --write` from the gdpn module's own docstrings; the",
           "test `docs.references` fails when this file differs from what the module says. The",
           "module is the library the `gdpn` program and the IDE call: the same request gives the",
           "same answer (docs/format.md, docs/queries.md).", "",
           "```python", "import gdpn", "m = gdpn.load(\"examples/factory\", seed=7)",
           "report = m.run(until=60)      # the figures gdpn run prints",
           "print(report[\"figures\"])", "print(m.analyze(\"AG not deadlock\")[\"answer\"])", "```", "",
           gdpn.__doc__.strip(), ""]
    names = sorted(n for n in dir(gdpn) if not n.startswith("_"))
    functions = [n for n in names if callable(getattr(gdpn, n)) and not inspect.isclass(getattr(gdpn, n))]
    errors = [n for n in names if inspect.isclass(getattr(gdpn, n)) and issubclass(getattr(gdpn, n), BaseException)]
    classes = [n for n in names if inspect.isclass(getattr(gdpn, n)) and n not in errors]
    out += ["## Functions", ""]
    for n in functions:
        out += entry(n, getattr(gdpn, n), "gdpn.")
    for c in classes:
        cls = getattr(gdpn, c)
        out += [f"## gdpn.{c}", "", inspect.cleandoc(cls.__doc__ or "").strip() or f"A gdpn {c}.", ""]
        for n, member in cls.__dict__.items():
            if n.startswith("_"):
                continue
            out += entry(n, member, f"{c}.", property_=isinstance(member, property))
    out += ["## Errors", "",
            "Each is raised with the file, line and column of the mistake where there is one.", ""]
    for n in errors:
        cls = getattr(gdpn, n)
        base = cls.__bases__[0].__name__
        out += [f"- `gdpn.{n}` ({base}): {inspect.cleandoc(cls.__doc__ or '').strip() or '-'}"]
    return "\n".join(out).rstrip() + "\n"


def entry(name, obj, owner, property_=False):
    if property_:
        sig, text = signature_and_text(obj.__doc__ or "")
        # a property's docstring is its text alone
        text = "\n".join(x for x in (sig, text) if x)
        return [f"### `{owner}{name}` (read-only)" if obj.fset is None else f"### `{owner}{name}`", "",
                text or "-", ""]
    doc = obj.__doc__ or ""
    if not doc and hasattr(obj, "__wrapped__"):
        doc = obj.__wrapped__.__doc__ or ""
    sig, text = signature_and_text(doc)
    if not sig.startswith(name + "("):
        # a function written in Python: inspect gives the signature, the docstring is all text
        try:
            sig = name + str(inspect.signature(obj))
        except (TypeError, ValueError):
            sig = name + "(...)"
        text = inspect.cleandoc(doc)
    # pybind11 spells `self: gdpn.Model`: the reader knows what self is
    sig = re.sub(r"\bself: [\w.]+(, )?", "", sig).replace("(, ", "(")
    return [f"### `{owner}{sig}`", "", text or "-", ""]


def example_paths(cli_md):
    """examples/... paths named in the commands' examples."""
    blocks = re.findall(r"```\nExamples?:\n(.*?)```", cli_md, re.S)
    return sorted({p for b in blocks for p in re.findall(r"\bexamples/[\w./-]+", b)})


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--gdpn", required=True, help="the gdpn program")
    mode = ap.add_mutually_exclusive_group(required=True)
    mode.add_argument("--write", action="store_true")
    mode.add_argument("--check", action="store_true")
    a = ap.parse_args()
    gdpn_program = os.path.abspath(a.gdpn)
    module_dir = Path(gdpn_program).parent.parent.parent / "python"
    if module_dir.is_dir():
        sys.path.insert(0, str(module_dir))
    import gdpn  # noqa: E402 (found beside the program's build)
    wanted = {ROOT / "docs/cli.md": cli_reference(gdpn_program), ROOT / "docs/python.md": python_reference(gdpn)}
    stale = []
    for path, text in wanted.items():
        have = path.read_text() if path.exists() else ""
        if have == text:
            continue
        if a.write:
            tmp = path.with_suffix(".md.tmp")
            tmp.write_text(text)
            tmp.replace(path)
            print(f"wrote {path.relative_to(ROOT)}")
        else:
            stale.append(path.relative_to(ROOT))
            diff = difflib.unified_diff(have.splitlines(), text.splitlines(), f"{path.name} (in the tree)",
                                        f"{path.name} (as written now)", n=1, lineterm="")
            print("\n".join(list(diff)[:24]), file=sys.stderr)
    readme = (ROOT / "README.md").read_text().count("\n")
    if readme > 120:
        stale.append(f"README.md: {readme} lines, over the 120 a front door may have")
    missing = [p for p in example_paths(wanted[ROOT / "docs/cli.md"]) if not (ROOT / p).exists()]
    for p in stale:
        if str(p).startswith("README"):
            print(f"{p.split(':')[0]}:121:1: error: {p.split(': ', 1)[1]}", file=sys.stderr)
            continue
        print(f"{p}:1:1: error: stale: the program or the module says otherwise "
              f"(python3 scripts/references.py --gdpn {a.gdpn} --write)", file=sys.stderr)
    for p in missing:
        print(f"docs/cli.md:1:1: error: an example of `gdpn COMMAND --help` names {p}, which is not there",
              file=sys.stderr)
    if a.check and not (stale or missing):
        print(f"docs/cli.md and docs/python.md are up to date; {len(example_paths(wanted[ROOT / 'docs/cli.md']))}"
              " example paths there")
    return 1 if stale or missing else 0


if __name__ == "__main__":
    sys.exit(main())
