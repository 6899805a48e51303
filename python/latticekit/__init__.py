"""latticekit: medical surface modelling filters for VTK.

Every filter is a VTK algorithm and composes with ``vtk`` classes in one
pipeline (VTK 9.1's wrappers take no keyword arguments in constructors, so
parameters are set with the ``Set`` methods):

>>> import latticekit
>>> from vtkmodules.vtkFiltersCore import vtkQuadricDecimation
>>> reader = latticekit.vtkLKMedicalImageReader()
>>> reader.SetFileName("head.nii.gz")
>>> bone = latticekit.vtkLKBoneSurfaceFilter()
>>> bone.SetIsoValue(300)
>>> bone.SetInputConnection(reader.GetOutputPort())
>>> flat = vtkQuadricDecimation()
>>> flat.SetInputConnection(bone.GetOutputPort())
>>> bone.GetIsoValue()
300.0
"""

# The VTK modules the wrapped classes derive from must be loaded first.
import vtkmodules.vtkCommonCore  # noqa: F401
import vtkmodules.vtkCommonDataModel  # noqa: F401
import vtkmodules.vtkCommonExecutionModel  # noqa: F401

from .LatticeKitFilters import *  # noqa: F401,F403

__version__ = "0.1.0"
