#!/usr/bin/env python3
"""Writes a model of N producer/consumer cells (a page type of 3 places and 2 transitions,
instanced N times on the top page), for the scale benchmark (bench/scale_bench.sh).

usage: bench/cells.py N OUT.gdpn.yaml [--linked]
  --linked: the top page's `start` feeds every cell's buffer (one connected net) instead of
            each cell running on its own
"""
import sys


def cells(n: int, linked: bool) -> str:
    out = ["gdpn: 1", "pages:", "  main:", "    places:",
           f"      feed: {{tokens: {n if linked else 1}}}", "    transitions:",
           "      start: {duration: 1}", "    instances:"]
    out += [f"      c{i}: cell" for i in range(n)]
    out += ["    arcs:", "      - feed -> start"]
    out += [f"      - start -> c{i}/buffer" for i in range(n)] if linked else ["      - start -> feed"]
    out += ["page_types:", "  cell:", "    references: [buffer]", "    places:",
            "      ready: {tokens: 1}", "      buffer: {capacity: 2}", "      free: {tokens: 1}",
            "    transitions:", "      produce: {duration: 2}",
            "      consume: {duration: {uniform: [1, 3]}}", "    arcs:",
            "      - ready -> produce", "      - produce -> buffer", "      - produce -> ready",
            "      - buffer -> consume", "      - free -> consume", "      - consume -> free"]
    return "\n".join(out) + "\n"


if __name__ == "__main__":
    if len(sys.argv) < 3 or not sys.argv[1].isdigit():
        sys.exit(__doc__)
    with open(sys.argv[2], "w", encoding="utf-8") as f:
        f.write(cells(int(sys.argv[1]), "--linked" in sys.argv[3:]))
