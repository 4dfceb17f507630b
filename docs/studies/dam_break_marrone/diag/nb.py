import sys, math
sys.path.insert(0, '.')
from vtu import read_vtu
a = read_vtu(sys.argv[1]); L = float(sys.argv[2]); dp = float(sys.argv[3]); ids = [int(s) for s in sys.argv[4:]]
X = a["Points"]; ph = a["phase"]; p = a["pressure"]; lam = a["free_surface"]; rho=a["density"]; pw=a["wall_pressure"]
h = 1.5*dp; ad = 7/(4*math.pi*h*h)
def W(r):
    q=r/h
    return ad*(1-q/2)**4*(1+2*q) if q<2 else 0
def F(r):  # dW/dr / r
    q=r/h
    return ad*(-5*q*(1-q/2)**3)/(h*r*1.0)*1.0 if q<2 else 0
rg=1000*9.81*0.6
idx = {a["id"][i]:i for i in range(len(X)) if ph[i]==0}
wdp=W(dp)
for pid in ids:
    i = idx[pid]
    sh=[0,0]; gl=[0,0]; shw=[0,0]; ap=[0,0]; apw=[0,0]
    nf=0; nw=0
    print("id",pid,"x/dp from face %.3f y %.4f p* %.3f lam %.2f"%((L-X[i][0])/dp, X[i][1], p[i]/rg, lam[i]))
    for j in range(len(X)):
        if j==i: continue
        rx=X[i][0]-X[j][0]; ry=X[i][1]-X[j][1]; r=math.hypot(rx,ry)
        if r>=2*h: continue
        f=F(r); vj = dp*dp if ph[j]!=0 else dp*dp*1000/rho[j]
        g=(f*rx,f*ry); q=W(r)/wdp
        c=(1+0.2*q**4)*vj
        sh[0]+=c*g[0]; sh[1]+=c*g[1]; gl[0]+=vj*g[0]; gl[1]+=vj*g[1]
        pj = p[j] if ph[j]==0 else pw[j]
        fp = -(p[i]+pj)*vj/rho[i]
        if ph[j]!=0:
            shw[0]+=c*g[0]; shw[1]+=c*g[1]; nw+=1; apw[0]+=fp*g[0]; apw[1]+=fp*g[1]
        else:
            nf+=1; ap[0]+=fp*g[0]; ap[1]+=fp*g[1]
        if r < 1.0*dp: print("   close: %s id %d r/dp %.3f dx/dp %+.2f dy/dp %+.2f p* %.3f" % ("wall" if ph[j] else "fluid", a["id"][j], r/dp, -rx/dp, -ry/dp, pj/rg))
    hU=-4*h*4.852216
    s=[hU*sh[0],hU*sh[1]]; n=math.hypot(*gl); nn=(gl[0]/n,gl[1]/n); sd=s[0]*nn[0]+s[1]*nn[1]
    st=[s[0]-sd*nn[0], s[1]-sd*nn[1]]
    print("  nf %d nw %d shift full (%.3f, %.3f) wallpart (%.3f, %.3f) gl dir (%.2f,%.2f) tangential (%.3f, %.3f)"%(nf,nw,s[0],s[1],hU*shw[0],hU*shw[1],nn[0],nn[1],st[0],st[1]))
    print("  pressure acc fluid (%.0f,%.0f) wall (%.0f,%.0f)"%(ap[0],ap[1],apw[0],apw[1]))
