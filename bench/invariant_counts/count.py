import sys
from collections import Counter
base=sys.argv[1]
mult=[int(x) for x in open(base+'.mult').read().split()]
lines=open(base+'.ray').read().split('\n')
n,m=map(int,lines[0].split())
total=0; sizes=Counter()
for l in lines[1:1+n]:
    v=[int(x) for x in l.split()]
    p=1
    for i,x in enumerate(v):
        if x: p*=mult[i]
    total+=p; sizes[sum(1 for x in v if x)]+=1
print(base,'reduced rays',n,'full minimal T-semiflows',total, 'support sizes', sorted(sizes.items()))
