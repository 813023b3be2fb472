import sys; sys.path.insert(0, __import__('os').path.dirname(__file__))
from parse import load
from collections import defaultdict
# usage: tofti2.py NET.pnml red|full OUT  (writes OUT.mat for 4ti2; with red, OUT.mult: class sizes)
path, mode, out = sys.argv[1], sys.argv[2], sys.argv[3]
P,T,C = load(path)
if mode=='red':
    classes=defaultdict(list)
    for t,c in enumerate(C): classes[tuple(sorted(c.items()))].append(t)
    cols=[dict(k) for k in classes]
    open(out+'.mult','w').write(' '.join(str(len(v)) for v in classes.values())+'\n')
else:
    cols=C
# matrix rows = places, cols = transitions
with open(out+'.mat','w') as f:
    f.write(f'{len(P)} {len(cols)}\n')
    for p in range(len(P)):
        f.write(' '.join(str(c.get(p,0)) for c in cols)+'\n')
