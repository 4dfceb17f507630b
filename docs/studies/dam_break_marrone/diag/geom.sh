# usage: geom N  -> prints --set args for H/N
geom() {
python3 - "$1" <<'PY'
import sys
n=int(sys.argv[1]); H=0.6; dp=H/n; L=round(5.366*H/dp)*dp; t=3*dp
print(" ".join(["dp=%r"%dp,"domain.min=[%r,%r]"%(-t,-t),"domain.max=[%r,4.0]"%(L+t),
"bodies.1.shape.difference.0.box.min=[%r,%r]"%(-t,-t),"bodies.1.shape.difference.0.box.max=[%r,4.0]"%(L+t),
"bodies.1.shape.difference.1.box.max=[%r,4.0]"%L,"probes.list.1.center=[%r,0.006]"%L]))
PY
}
