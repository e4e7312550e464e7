import math,glob
HA=27.211386245988
def walls(N,n0):
    ns=[n0+5*k for k in range(N)]
    g=ns[0]
    for n in ns: g=math.gcd(g,n)
    return ns,g
def radii(fn,counts):
    L=open(fn).read().split('\n'); n=int(L[0]); at=[list(map(float,l.split()[1:4])) for l in L[2:2+n]]
    out=[];i=0
    for c in counts:
        out.append(sum(math.hypot(a[0],a[1]) for a in at[i:i+c])/c); i+=c
    return out
rows={}
for l in open('results.txt'):
    p=l.split()
    if len(p)<5: continue
    N,n0,atoms,E,e=int(p[0]),int(p[1]),int(p[2]),float(p[3]),float(p[4])
    ns,g=walls(N,n0); counts=[4*n//g for n in ns]
    R=radii(f's{N}-{n0}-relaxed.xyz',counts)
    area=None
    rows.setdefault(N,[]).append((n0,e,R,atoms,E))
# area per atom from the relaxed T: the xyz comment has mesochain:translation
def fitline(x,y):
    n=len(x); mx=sum(x)/n; my=sum(y)/n
    sxx=sum((a-mx)**2 for a in x); sxy=sum((a-mx)*(b-my) for a,b in zip(x,y))
    s=sxy/sxx; c=my-s*mx; res=[b-(c+s*a) for a,b in zip(x,y)]
    se=math.sqrt(sum(r*r for r in res)/(n-2)/sxx) if n>2 else 0
    return s,c,se,max(abs(r) for r in res)
for N,r in sorted(rows.items()):
    # per-atom area: T * circumference / atoms-per-wall for the inner wall
    T=float([t for t in open(f's{N}-{r[0][0]}-relaxed.xyz').read().split('\n')[1].split() if t.startswith('mesochain:translation=')][0].split('=')[1])
    aat=3*math.sqrt(3)/4*(T/math.sqrt(3))**2  # armchair T = a = sqrt3 b  -> b = T/sqrt3
    if N==1: x=[1/(q[2][0]**2) for q in r]
    else: x=[1/(q[2][0]*q[2][1]) for q in r]
    y=[q[1] for q in r]
    s,c,se,mr=fitline(x,y)
    D=2*s*HA/aat
    print(f"N={N}: T={T:.5f} A, area/atom {aat:.4f} A2, slope -> D1_eff = {D:.4f} +- {2*se*HA/aat:.4f} eV, max residual {mr*HA*1000:.3f} meV/atom, radii", [ [round(v,3) for v in q[2]] for q in r])
