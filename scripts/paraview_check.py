"""Open a monosph .pvd in ParaView (pvbatch or pvpython) and report what ParaView reads back.

    pvbatch scripts/paraview_check.py OUT.pvd [--png FILE]

Goes to the last time step and prints the number of points, the time steps and, for every
point-data array, its components and ranges. Exits 1 with a one-line message if the last frame
has no points or no arrays. --png renders the last frame (Points, coloured by the first scalar
array) to FILE. Usually run through scripts/paraview-check (Debian 12's ParaView 5.11 in a chroot).
"""
import argparse
import sys

from paraview import servermanager
from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetAnimationScene, OpenDataFile,
                             ResetCamera, SaveScreenshot, Show, UpdatePipeline)


def fail(msg):
    print(f"paraview_check: FAIL: {msg}", flush=True)
    sys.exit(1)


def fmt_range(r):
    return f"[{r[0]:.6g}, {r[1]:.6g}]"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("pvd")
    ap.add_argument("--png", metavar="FILE")
    args = ap.parse_args()

    src = OpenDataFile(args.pvd)
    if src is None:
        fail(f"ParaView has no reader for {args.pvd}")
    times = list(getattr(src, "TimestepValues", None) or [])
    if isinstance(times, float):
        times = [times]
    last = times[-1] if times else 0.0
    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.AnimationTime = last
    UpdatePipeline(time=last, proxy=src)

    info = src.GetDataInformation()
    npts = info.GetNumberOfPoints()
    print(f"file:        {args.pvd}")
    print(f"reader:      {src.GetXMLName()}  (ParaView {servermanager.vtkSMProxyManager.GetParaViewSourceVersion()})")
    print(f"time steps:  {len(times)}   last time: {last:.9g}")
    print(f"points:      {npts}   cells: {info.GetNumberOfCells()}")

    arrays = list(src.PointData.values())
    first_scalar = None
    for a in arrays:
        nc = a.GetNumberOfComponents()
        # As ParaView shows them: the file's names, else ParaView's defaults (X Y Z, 0 1 ...).
        names = [a.GetComponentName(c) or str(c) for c in range(nc)] if nc > 1 else []
        line = f"  {a.Name:<24} {nc:>2} comp"
        if names:
            line += f"  ({', '.join(names)})"
        if nc == 1:
            line += f"  range {fmt_range(a.GetRange(0))}"
            if first_scalar is None:
                first_scalar = a.Name
        print(line)
        if nc > 1:
            for c in range(nc):
                label = names[c] if names else str(c)
                print(f"      {label:<8} {fmt_range(a.GetRange(c))}")
            print(f"      {'|mag|':<8} {fmt_range(a.GetRange(-1))}")
    print(f"point arrays: {len(arrays)}")

    if npts == 0:
        fail(f"last frame (t={last:.9g}) of {args.pvd} has 0 points")
    if not arrays:
        fail(f"last frame (t={last:.9g}) of {args.pvd} has no point-data arrays")

    if args.png:
        view = GetActiveViewOrCreate("RenderView")
        view.ViewSize = [1000, 700]
        view.ViewTime = last
        disp = Show(src, view)
        disp.SetRepresentationType("Points")
        disp.PointSize = 3
        for pref in ("pressure", "density"):
            if pref in src.PointData.keys():
                first_scalar = pref
                break
        if first_scalar:
            ColorBy(disp, ("POINTS", first_scalar))
            disp.RescaleTransferFunctionToDataRange(True, False)
            disp.SetScalarBarVisibility(view, True)
        bounds = src.GetDataInformation().GetBounds()
        if bounds[5] > bounds[4]:  # 3D: an oblique view instead of looking down z
            view.CameraPosition = [1.0, -2.0, 1.2]
            view.CameraFocalPoint = [0.0, 0.0, 0.0]
            view.CameraViewUp = [0.0, 0.0, 1.0]
        ResetCamera(view)
        SaveScreenshot(args.png, view, ImageResolution=[1000, 700])
        print(f"png:         {args.png}  (coloured by {first_scalar or 'solid colour'})")
    print("paraview_check: OK")


if __name__ == "__main__":
    main()
