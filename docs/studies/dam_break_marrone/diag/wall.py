import sys, math
sys.path.insert(0, '.')
from vtu import read_vtu
a = read_vtu(sys.argv[1]); L = float(sys.argv[2]); dp = float(sys.argv[3])
X = a["Points"]; ph = a["phase"]; p = a["pressure"]; lam = a["free_surface"]; v = a["velocity"]; sh=a["shift_rate"]; acc=a["acceleration"]
rg = 1000*9.81*0.6
print("t*", a["TimeValue"][0]*math.sqrt(9.81/0.6))
close = [i for i in range(len(X)) if ph[i]==0 and (L - X[i][0]) < 0.5*dp]
close.sort(key=lambda i: (L-X[i][0]))
print("fluid closer than 0.5 dp to right wall face:", len(close))
for i in close[:30]:
    print("id %6d d/dp %+.2f y %.4f p* %+.3f lam %.2f vx %+.2f vy %+.2f shx %+.3f shy %+.3f ax %+.0f ay %+.0f" % (a["id"][i], (L-X[i][0])/dp, X[i][1], p[i]/rg, lam[i], v[i][0], v[i][1], sh[i][0], sh[i][1], acc[i][0], acc[i][1]))
