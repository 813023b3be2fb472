# checks the duplicate rule: expand the classes of equal transitions to at most `cap` members, count the
# extreme rays with 4ti2-rays, compare with sum over the reduced rays of prod(min(mult,cap)) over its support
import sys, subprocess
base, cap = sys.argv[1], int(sys.argv[2])
mult=[int(x) for x in open(base+'.mult').read().split()]
lines=open(base+'.mat').read().split('\n'); m,n=map(int,lines[0].split())
rows=[[int(x) for x in l.split()] for l in lines[1:1+m]]
cols=[]
for j in range(n):
    for k in range(min(mult[j],cap)): cols.append(j)
with open('dup.mat','w') as f:
    f.write(f'{m} {len(cols)}\n')
    for r in rows: f.write(' '.join(str(r[j]) for j in cols)+'\n')
subprocess.run(['4ti2-rays','-q','dup'],check=True)
got=int(open('dup.ray').readline().split()[0])
rl=open(base+'.ray').read().split('\n'); nr=int(rl[0].split()[0])
exp=0
for l in rl[1:1+nr]:
    v=[int(x) for x in l.split()]; p=1
    for j,x in enumerate(v):
        if x: p*=min(mult[j],cap)
    exp+=p
print('cap',cap,'columns',len(cols),'4ti2 rays',got,'predicted',exp)
