"""Mesh checks shared by the Python tests."""
from vtkmodules.vtkFiltersCore import vtkFeatureEdges


def open_edges(mesh, non_manifold=True):
    """The border edges of `mesh` (and its non-manifold ones unless told not to), as a vtkPolyData
    of lines; none for a closed, manifold surface. Coinciding points are merged, as vtkFeatureEdges does."""
    edges = vtkFeatureEdges()
    edges.SetInputData(mesh)
    edges.BoundaryEdgesOn()
    edges.SetNonManifoldEdges(non_manifold)
    edges.FeatureEdgesOff()
    edges.ManifoldEdgesOff()
    edges.Update()
    return edges.GetOutput()
