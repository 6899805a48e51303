# Makes the planner test data: tests/data/mandible_session.json (a split-mode stroke
# along the plane x = centre of the TCIA mandible, cut, lattice, Metro) and
# tests/data/mandible_events.log (a closed circle stroke drawn with the mouse on the
# condyle, then the cut and lattice keys, then the cut-out segment moved and
# rotated with the mouse and the session saved; vtkInteractorEventRecorder format).
# Run from the repository root after a build: xvfb-run -a /usr/bin/python3 scripts/make_planner_test_data.py
import json
import sys
sys.path.insert(0, 'build/python')
import latticekit
from vtkmodules.vtkCommonDataModel import vtkPlane
from vtkmodules.vtkFiltersCore import vtkCutter, vtkStripper
r = latticekit.vtkLKMedicalImageReader(); r.SetFileName('sample_data/mandible-tcia/test_oncologist_0522c0017_Mandible.nrrd')
b = latticekit.vtkLKBoneSurfaceFilter(); b.SetInputConnection(r.GetOutputPort()); b.Update()
s = b.GetOutput()
plane = vtkPlane(); plane.SetOrigin(s.GetCenter()); plane.SetNormal(1, 0, 0)
c = vtkCutter(); c.SetInputData(s); c.SetCutFunction(plane)
st = vtkStripper(); st.SetInputConnection(c.GetOutputPort()); st.Update()
o = st.GetOutput(); cell = o.GetCell(0)
n = cell.GetNumberOfPoints(); step = max(1, n // 40)
pts = [list(round(v, 4) for v in o.GetPoint(cell.GetPointId(k))) for k in range(0, n, step)]
pts.append(pts[0])
print(o.GetNumberOfCells(), n, len(pts))
session = {"strokes": [{"mode": "split", "points": pts}], "cut": True, "capping": True, "lattice": True, "latticeVertices": 400, "metro": True}
json.dump(session, open('tests/data/mandible_session.json', 'w'), indent=1)

import math, sys
sys.path.insert(0, 'build/python')
import latticekit
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow, vtkActor, vtkPolyDataMapper, vtkCellPicker
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
import vtkmodules.vtkRenderingOpenGL2
r = latticekit.vtkLKMedicalImageReader(); r.SetFileName('sample_data/mandible-tcia/test_oncologist_0522c0017_Mandible.nrrd')
b = latticekit.vtkLKBoneSurfaceFilter(); b.SetInputConnection(r.GetOutputPort()); b.Update()
m = vtkPolyDataMapper(); m.SetInputData(b.GetOutput()); a = vtkActor(); a.SetMapper(m)
ren = vtkRenderer(); ren.AddActor(a)
win = vtkRenderWindow(); win.SetOffScreenRendering(1); win.AddRenderer(ren); win.SetSize(1000, 750)
ren.ResetCamera(); win.Render()
picker = vtkCellPicker(); picker.SetTolerance(0.0005)
# find a screen centre where a circle of radius R hits the bone all around
best = None
for cx in range(200, 800, 10):
    for cy in range(150, 600, 10):
        ok = all(picker.Pick(cx + 22 * math.cos(t), cy + 22 * math.sin(t), 0, ren) for t in [k * math.pi / 8 for k in range(16)]) and picker.Pick(cx, cy, 0, ren)
        if ok:
            best = (cx, cy); break
    if best: break
print('centre', best)
cx, cy = best
lines = ['# StreamVersion 1.1', '# A closed stroke (a circle of 22 pixels) on the mandible, nearest-edges mode, then cut and lattice.']
def ev(name, x, y, key='0', sym='0'):
    lines.append('%s %d %d 0 0 %s %d %s' % (name, x, y, key, 0 if sym == '0' else 1, sym))
for k in ['2', 'd']:
    for e in ['KeyPressEvent', 'CharEvent', 'KeyReleaseEvent']:
        ev(e, cx, cy, k, k)
pts = [(int(round(cx + 22 * math.cos(2 * math.pi * k / 48))), int(round(cy + 22 * math.sin(2 * math.pi * k / 48)))) for k in range(49)]
ev('LeftButtonPressEvent', *pts[0])
for p in pts[1:]:
    ev('MouseMoveEvent', *p)
ev('LeftButtonReleaseEvent', *pts[-1])
for k in ['x', 'l']:
    for e in ['KeyPressEvent', 'CharEvent', 'KeyReleaseEvent']:
        ev(e, cx, cy, k, k)
# Pick the segment (the smallest piece: the cut-out cap), switch to move mode,
# drag it 60 pixels right and 20 up, then rotate it with shift+drag, and save.
for k in ['n', 'g']:
    for e in ['KeyPressEvent', 'CharEvent', 'KeyReleaseEvent']:
        ev(e, 500, 375, k, k)
ev('LeftButtonPressEvent', 500, 375)
for k in range(1, 7):
    ev('MouseMoveEvent', 500 + 10 * k, 375 + round(20 * k / 6))
ev('LeftButtonReleaseEvent', 560, 395)
lines.append('LeftButtonPressEvent 500 375 0 1 0 0 0')
for k in range(1, 5):
    lines.append('MouseMoveEvent %d 375 0 1 0 0 0' % (500 + 10 * k))
lines.append('LeftButtonReleaseEvent 540 375 0 1 0 0 0')
for e in ['KeyPressEvent', 'CharEvent', 'KeyReleaseEvent']:
    ev(e, 500, 375, 'w', 'w')
open('tests/data/mandible_events.log', 'w').write('\n'.join(lines) + '\n')
