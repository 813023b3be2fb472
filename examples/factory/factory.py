# The factory's globals: the paint's colour, and the records the summary reads. Every script
# sees these names. As in the dissertation (section 7.1), no script holds a loop or a
# condition: what happens next is decided by the net and by the sensors on its arcs.

PAINT = (0.95, 0.4, 0.05)  # the colour of a painted box
paints = []                # each box a station painted, once per painting
strikes = []               # (time, name) for each body a rod's tip met (a box, a stop)


def piled():
    return set(sim.place("factory/piled").d0)


def summary():
    return {
        "boxes at the end of the line": len(piled()),
        "painted among them": len(piled() & set(paints)),
        "unpainted among them": len(piled() - set(paints)),
        "share of those painted": (100 * len(piled() & set(paints)) / max(1, len(piled())), "%"),
        "boxes painted twice": len(paints) - len(set(paints)),
        "rod strikes": len(strikes),
    }
