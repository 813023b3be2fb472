import sys, xml.etree.ElementTree as ET
from fractions import Fraction
def load(path):
    t = ET.parse(path).getroot()
    ns = ''
    def tag(e): return e.tag.split('}')[-1]
    places, trans, arcs = [], [], []
    for e in t.iter():
        k = tag(e)
        if k == 'place': places.append(e.get('id'))
        elif k == 'transition': trans.append(e.get('id'))
        elif k == 'arc':
            w = 1
            for c in e.iter():
                if tag(c) == 'inscription':
                    for d in c.iter():
                        if tag(d) == 'text': w = int(d.text.strip())
            arcs.append((e.get('source'), e.get('target'), w))
    pi = {p:i for i,p in enumerate(places)}; ti = {x:i for i,x in enumerate(trans)}
    C = [dict() for _ in trans]  # per transition: place -> value
    for s, d, w in arcs:
        if s in pi: C[ti[d]][pi[s]] = C[ti[d]].get(pi[s], 0) - w
        else: C[ti[s]][pi[d]] = C[ti[s]].get(pi[d], 0) + w
    C = [{p:v for p,v in c.items() if v} for c in C]
    return places, trans, C
