"""Small rendering helpers shared by the examples."""
from vtkmodules.vtkCommonDataModel import vtkDataObject
from vtkmodules.vtkFiltersExtraction import vtkExtractEdges
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkWindowToImageFilter


def edge_actor(mesh):
    """The edges of `mesh` (a vtkPolyData or an algorithm's output port) as a dark line actor."""
    edges = vtkExtractEdges()
    if isinstance(mesh, vtkDataObject):
        edges.SetInputData(mesh)
    else:
        edges.SetInputConnection(mesh)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(edges.GetOutputPort())
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.1, 0.1, 0.1)
    return actor


def save_png(window, path):
    """Render `window` and write what it shows to the PNG file `path`."""
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    writer = vtkPNGWriter()
    writer.SetInputConnection(grab.GetOutputPort())
    writer.SetFileName(path)
    writer.Write()
    print("wrote", path)
