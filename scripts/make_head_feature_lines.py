# Makes sample_data/cthead/head_feature_lines.txt: ellipses drawn in front and side
# views of the CT head skin (-400 HU), picked onto the surface. Run from the
# repository root after a build: xvfb-run -a /usr/bin/python3 scripts/make_head_feature_lines.py
import sys, math
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow, vtkActor, vtkPolyDataMapper, vtkWindowToImageFilter, vtkCellPicker
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData, vtkCellArray
from vtkmodules.vtkFiltersCore import vtkTubeFilter
import vtkmodules.vtkRenderingOpenGL2
sys.path.insert(0, 'build/python')
import latticekit as lk
from vtkmodules.vtkCommonCore import vtkLogger
vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_ERROR)
r = lk.vtkLKMedicalImageReader(); r.SetFileName('sample_data/cthead/cthead_hu_approx.nii.gz')
b = lk.vtkLKBoneSurfaceFilter(); b.SetInputConnection(r.GetOutputPort()); b.SetIsoValue(-400); b.SetLabelMapMode(0); b.Update()
skin = b.GetOutput()
m = vtkPolyDataMapper(); m.SetInputData(skin); m.ScalarVisibilityOff()
a = vtkActor(); a.SetMapper(m)
ren = vtkRenderer(); ren.AddActor(a); ren.SetBackground(1,1,1)
rw = vtkRenderWindow(); rw.SetOffScreenRendering(1); rw.AddRenderer(ren); rw.SetSize(600, 600)
c = skin.GetCenter()
views = {'front': ((0,-1,0), (0,0,-1)), 'left': ((-1,0,0), (0,0,-1)), 'right': ((1,0,0), (0,0,-1))}
def setview(name):
    d, up = views[name]
    cam = ren.GetActiveCamera(); cam.SetFocalPoint(c); cam.SetPosition(c[0]+500*d[0], c[1]+500*d[1], c[2]+500*d[2]); cam.SetViewUp(up)
    cam.ParallelProjectionOn(); ren.ResetCamera(); rw.Render()
# (view, centre x, centre y (image rows from top), rx, ry)
loops = [('front', 285, 262, 30, 16, 'right orbit'), ('front', 372, 262, 30, 16, 'left orbit'),
         ('front', 320, 298, 24, 34, 'nose'), ('front', 322, 357, 48, 16, 'mouth'),
         ('left', 328, 322, 34, 50, 'left ear'), ('right', 272, 322, 34, 50, 'right ear')]
picker = vtkCellPicker(); picker.SetTolerance(0.0005)
out = open('sample_data/cthead/head_feature_lines.txt', 'w')
out.write('# Feature lines on the CT head\'s skin (-400 HU), for the lattice fit benchmark\n'
          '# (seed 004, fig. 4.6: orbits, nose, mouth and ears). World coordinates of the\n'
          '# volume (mm); each block is one closed polyline (its last point repeats the\n'
          '# first), snapped to mesh edge paths at run time (lk::edgePathThrough).\n'
          '# Made by picking ellipses drawn in front and side views (scripts in NOTES.md).\n')
pts = vtkPoints(); lines = vtkCellArray()
for view, cx, cy, rx, ry, name in loops:
    setview(view)
    out.write('# %s\n' % name)
    ids = []
    for k in range(49):
        t = 2 * math.pi * (k % 48) / 48
        x, y = cx + rx * math.cos(t), 600 - (cy + ry * math.sin(t))
        if picker.Pick(x, y, 0, ren):
            p = picker.GetPickPosition()
            out.write('%.3f %.3f %.3f\n' % p)
            ids.append(pts.InsertNextPoint(p))
    lines.InsertNextCell(len(ids))
    for i in ids: lines.InsertCellPoint(i)
out.close()
pd = vtkPolyData(); pd.SetPoints(pts); pd.SetLines(lines)
tube = vtkTubeFilter(); tube.SetInputData(pd); tube.SetRadius(1.0)
lm = vtkPolyDataMapper(); lm.SetInputConnection(tube.GetOutputPort()); la = vtkActor(); la.SetMapper(lm); la.GetProperty().SetColor(1, 0, 0)
ren.AddActor(la)
for name in ['front', 'left', 'right']:
    setview(name)
    wi = vtkWindowToImageFilter(); wi.SetInput(rw); wi.Update()
    p = vtkPNGWriter(); p.SetFileName('head_feature_lines_%s.png' % name); p.SetInputConnection(wi.GetOutputPort()); p.Write()
