import sys
base=sys.argv[1]
lines=open(base+'.mat').read().split('\n')
m,n=map(int,lines[0].split())
with open(base+'.in','w') as f:
    f.write(f'amb_space {n}\nequations {m}\n')
    for l in lines[1:1+m]: f.write(l+'\n')
    f.write(f'inequalities {n}\n')
    for i in range(n): f.write(' '.join('1' if j==i else '0' for j in range(n))+'\n')
    f.write('ExtremeRays\n')
