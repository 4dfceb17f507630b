import sys, math
sys.path.insert(0, '.')
from vtu import read_vtu
a = read_vtu(sys.argv[1]); L = float(sys.argv[2]); dp = float(sys.argv[3])
X = a["Points"]; ph = a["phase"]; p = a["pressure"]; lam = a["free_surface"]; v = a["velocity"]; rho=a["density"]
print(list(a.keys()))
fl = [i for i in range(len(X)) if ph[i] == 0]
print("phases", set(ph))
jet = [i for i in fl if X[i][0] > L - 0.15 and X[i][1] > 0.4]
jet.sort(key=lambda i: -X[i][1])
rg = 1000*9.81*0.6
print("jet particles", len(jet))
for i in jet[:40]:
    print("id %6d x %.4f (L-x)/dp %.2f y %.4f p* %+.3f lam %.2f v (%.2f, %.2f) rho %.2f" % (a["id"][i], X[i][0], (L-X[i][0])/dp, X[i][1], p[i]/rg, lam[i], v[i][0], v[i][1], rho[i]))
neg = [i for i in jet if p[i] < 0]
print("jet with p<0:", len(neg), "min p*", min(p[i] for i in jet)/rg)
