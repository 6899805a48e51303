#!/usr/bin/python3
"""latticekit's Metro against MeshLab's Hausdorff Distance filter (vcglib, the
library Metro itself is built on), on the bundled TCIA mandible against a
2,000-vertex vtkQuadricDecimation copy and against the surface of a refined
2,000-vertex lattice (tessellated as latticekit-fit --surface does), both
directions.

usage (after a build; needs Debian's meshlab and xvfb-run, which the project
does not depend on):
  PYTHONPATH=build/python xvfb-run -a /usr/bin/python3 scripts/metro_against_meshlab.py [FOLDER]

Vertex samples only: the same points, so the distances must agree to MeshLab's
float precision. Face samples only, two million per direction by Monte Carlo
in both: the means must agree to sampling noise (MeshLab's mean counts each
face sample once, with face counts proportional to area, which estimates the
same area-weighted mean as latticekit's default).
"""
import os
import re
import subprocess
import sys
import tempfile

import latticekit
from vtkmodules.vtkFiltersCore import vtkQuadricDecimation, vtkTriangleFilter
from vtkmodules.vtkIOPLY import vtkPLYWriter

MANDIBLE = 'sample_data/mandible-tcia/test_oncologist_0522c0017_Mandible.nrrd'

FILTER = """ <filter name="Hausdorff Distance">
  <Param type="RichMesh" value="{a}" name="SampledMesh"/>
  <Param type="RichMesh" value="{b}" name="TargetMesh"/>
  <Param type="RichBool" value="false" name="SaveSample"/>
  <Param type="RichBool" value="{vertex}" name="SampleVert"/>
  <Param type="RichBool" value="false" name="SampleEdge"/>
  <Param type="RichBool" value="false" name="SampleFauxEdge"/>
  <Param type="RichBool" value="{face}" name="SampleFace"/>
  <Param type="RichInt" value="{n}" name="SampleNum"/>
  <Param type="RichAbsPerc" value="50" min="0" max="200" name="MaxDist"/>
 </filter>
"""


def write_ply(pd, path):
    tri = vtkTriangleFilter()
    tri.SetInputData(pd)
    w = vtkPLYWriter()
    w.SetInputConnection(tri.GetOutputPort())
    w.SetFileName(path)
    w.SetFileTypeToBinary()
    w.Write()


def meshlab(a, b, vertex, face, n, folder):
    script = os.path.join(folder, 'hausdorff.mlx')
    with open(script, 'w') as f:
        f.write('<!DOCTYPE FilterScript>\n<FilterScript>\n')
        for sa, sb in ((0, 1), (1, 0)):
            f.write(FILTER.format(a=sa, b=sb, vertex=str(vertex).lower(), face=str(face).lower(), n=n))
        f.write('</FilterScript>\n')
    out = subprocess.run(['meshlabserver', '-i', a, '-i', b, '-s', script],
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True).stdout
    found = re.findall(r'LOG: 2\s+min : \S+\s+max (\S+)\s+mean : (\S+)\s+RMS : (\S+)', out)
    # Each filter logs absolute values, then values relative to its bbox diagonal.
    return [tuple(float(x) for x in found[i]) for i in (0, 2)]


def ours(a, b, vertex, face, n):
    m = latticekit.vtkLKMetroFilter()
    m.SetInputData(a)
    m.SetTargetData(b)
    m.SetVertexSampling(vertex)
    m.SetEdgeSampling(False)
    m.SetFaceSampling(face)
    if face:
        m.SetNumberOfSamples(n)
    m.Update()
    return [(m.GetForwardMaximum(), m.GetForwardMean(), m.GetForwardRMS()),
            (m.GetBackwardMaximum(), m.GetBackwardMean(), m.GetBackwardRMS())]


def main(argv):
    folder = argv[1] if len(argv) > 1 else tempfile.mkdtemp()
    reader = latticekit.vtkLKMedicalImageReader()
    reader.SetFileName(MANDIBLE)
    bone = latticekit.vtkLKBoneSurfaceFilter()
    bone.SetInputConnection(reader.GetOutputPort())
    bone.Update()
    surface = bone.GetOutput()
    flat = vtkQuadricDecimation()
    flat.SetInputData(surface)
    flat.SetTargetReduction(1.0 - 2000.0 / surface.GetNumberOfPoints())
    flat.VolumePreservationOff()
    flat.Update()
    fit = latticekit.vtkLKLatticeFitFilter()
    fit.SetInputData(surface)
    fit.SetTargetNumberOfVertices(2000)
    fit.RefinementOn()
    fit.ComputeErrorOff()
    smooth = latticekit.vtkLKLatticeSurfaceFilter()
    smooth.SetInputConnection(fit.GetOutputPort())
    smooth.SetResolution(8)
    smooth.Update()
    b = os.path.join(folder, 'mandible.ply')
    write_ply(surface, b)
    print('B: the mandible, %d vertices' % surface.GetNumberOfPoints())
    for title, mesh in (('vtkQuadricDecimation', flat.GetOutput()), ('refined lattice surface', smooth.GetOutput())):
        a = os.path.join(folder, 'a.ply')
        write_ply(mesh, a)
        print('\nA: %s, %d vertices' % (title, mesh.GetNumberOfPoints()))
        print('%-22s %-7s %12s %12s %12s' % ('samples', 'dir', 'max', 'mean', 'RMS'))
        for label, vertex, face, n in (('vertices only', True, False, 10**7),
                                       ('faces only, 2 M', False, True, 2 * 10**6)):
            ml = meshlab(a, b, vertex, face, n, folder)
            lk = ours(mesh, surface, vertex, face, n)
            for d, name in enumerate(('A -> B', 'B -> A')):
                print('%-22s %-7s %12.6f %12.6f %12.6f   latticekit' % ((label, name) + lk[d]))
                print('%-22s %-7s %12.6f %12.6f %12.6f   MeshLab' % (('', '') + ml[d]))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
