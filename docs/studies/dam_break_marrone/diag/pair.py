import csv, math, sys
rows = list(csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith('#')))
dp = float(sys.argv[2]); TS = math.sqrt(9.81/0.6); L=float(sys.argv[3]); t0=float(sys.argv[4]) if len(sys.argv)>4 else 2.0
g = lambda r,k: float(r[k])
last = None; Iv = 0; Is = 0
for r in rows:
    t = g(r,'time')*TS
    dx = g(r,'b_position_x')-g(r,'a_position_x'); dy = g(r,'b_position_y')-g(r,'a_position_y'); d = math.hypot(dx,dy)
    ex, ey = dx/d, dy/d
    vr = (g(r,'b_velocity_x')-g(r,'a_velocity_x'))*ex + (g(r,'b_velocity_y')-g(r,'a_velocity_y'))*ey
    sr = (g(r,'b_shift_rate_x')-g(r,'a_shift_rate_x'))*ex + (g(r,'b_shift_rate_y')-g(r,'a_shift_rate_y'))*ey
    if last is not None:
        dt = g(r,'time') - last
        Iv += vr*dt; Is += sr*dt
    last = g(r,'time')
    if t >= t0 and (int(round(t/0.002)) % 10 == 0 or t > 3.04):
        print("t* %.3f d/dp %.3f  wall a %.2f b %.2f ya %.3f  vrel %+.3f  shrel %+.3f  cum(v) %+.3f cum(s) %+.3f dp  rho a %.2f b %.2f lam a %.2f b %.2f" % (
            t, d/dp, (L-g(r,'a_position_x'))/dp, (L-g(r,'b_position_x'))/dp, g(r,'a_position_y'), vr, sr, Iv/dp, Is/dp, g(r,'a_density'), g(r,'b_density'), g(r,'a_free_surface'), g(r,'b_free_surface')))
