import sys, math
sys.path.insert(0, '.')
from vtu import read_vtu
a = read_vtu(sys.argv[1]); L = float(sys.argv[2]); dp = float(sys.argv[3]); ids = [int(s) for s in sys.argv[4:]]
X = a["Points"]; ph = a["phase"]; rho=a["density"]; v=a["velocity"]
h = 1.5*dp; ad = 7/(4*math.pi*h*h)
def F(r):
    q=r/h
    return ad*(-5*q*(1-q/2)**3)/(h*r) if q<2 else 0
idx = {a["id"][i]:i for i in range(len(X)) if ph[i]==0}
for pid in ids:
    i = idx[pid]; df=0; dw=0; dwx=0; dwy=0
    for j in range(len(X)):
        if j==i: continue
        rx=X[i][0]-X[j][0]; ry=X[i][1]-X[j][1]; r=math.hypot(rx,ry)
        if r>=2*h or r == 0: continue
        f=F(r); vj = dp*dp if ph[j]!=0 else dp*dp*1000/rho[j]
        vjx = v[j][0] if ph[j]==0 else 0; vjy = v[j][1] if ph[j]==0 else 0
        t = vj*f*((vjx-v[i][0])*rx + (vjy-v[i][1])*ry)
        if ph[j]==0: df+=t
        else: dw+=t; dwx += vj*f*(vjx-v[i][0])*rx; dwy += vj*f*(vjy-v[i][1])*ry
    print(pid, "drho fluid part %.0f wall part %.0f (x %.0f, y %.0f) stored %.0f" % (-rho[i]*df, -rho[i]*dw, -rho[i]*dwx, -rho[i]*dwy, a["density_rate"][i]))
