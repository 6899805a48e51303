#!/usr/bin/python3
"""Wrinkly surfaces on the example nets of figures 12 and 13 (seed 000), rendered to a PNG.

usage: PYTHONPATH=build/python xvfb-run -a /usr/bin/python3 python/examples/wrinkly_nets.py OUT.png [K]

Top row: the wrinkly surfaces (heights and colours through the IST, M_U = M_V = 1,
alpha0 = alpha1 = 0.5, K iterations, default 3) of the 2-direction (regular),
3-direction, 4-direction and annular nets. Bottom row: the same nets without
the IST (K = 0, the paper's "interpolation surface"), with the control mesh.
"""
import sys

import latticekit
from latticekit.rendering import edge_actor, save_png
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderWindow, vtkRenderer
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

NETS = [
    ("2-direction", dict(NetType=0, CellsU=8, CellsV=8)),
    ("3-direction", dict(NetType=1, Sides=6, Rings=3, EdgeCells=1)),
    ("4-direction", dict(NetType=1, Sides=8, Rings=3, EdgeCells=1)),
    ("annular", dict(NetType=2, Spokes=14, Rings=4)),
]


def net(settings):
    source = latticekit.vtkLKWrinklyNetSource()
    for key, value in settings.items():
        getattr(source, "Set" + key)(value)
    source.SetHeightAmplitude(0.35)
    return source


def main(argv):
    if len(argv) < 2:
        print(__doc__)
        return 2
    iterations = int(argv[2]) if len(argv) > 2 else 3
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(1600, 800)
    for col, (name, settings) in enumerate(NETS):
        for row, k in enumerate((iterations, 0)):
            source = net(settings)
            wrinkly = latticekit.vtkLKWrinklySurfaceFilter()
            wrinkly.SetInputConnection(source.GetOutputPort())
            wrinkly.SetIterations(k)
            if k == 0:
                wrinkly.SetResolution(3 ** iterations)
            normals = vtkPolyDataNormals()
            normals.SetInputConnection(wrinkly.GetOutputPort())
            normals.SplittingOff()
            normals.Update()
            out = normals.GetOutput()
            ren = vtkRenderer()
            ren.SetViewport(col / 4.0, 0.5 * (1 - row), (col + 1) / 4.0, 0.5 * (2 - row))
            ren.SetBackground(1, 1, 1)
            m = vtkPolyDataMapper()
            m.SetInputData(out)
            m.SetScalarModeToUsePointFieldData()
            m.SelectColorArray("Colors")
            m.SetColorModeToDirectScalars()
            a = vtkActor()
            a.SetMapper(m)
            ren.AddActor(a)
            if row == 1:
                ren.AddActor(edge_actor(source.GetOutputPort()))
            cam = ren.GetActiveCamera()
            cam.SetPosition(0.4, -1.0, 1.1)
            cam.SetFocalPoint(0, 0, 0)
            cam.SetViewUp(0, 0, 1)
            ren.ResetCamera()
            cam.Zoom(1.25)
            window.AddRenderer(ren)
            print(f"{name}: K {k}, {out.GetNumberOfPolys()} triangles")
    save_png(window, argv[1])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
