"""Small rendering helpers shared by the examples."""
import os

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
    """Render `window` and write what it shows to the PNG file `path`.

    The picture is made in memory and written whole or not at all (a
    temporary file beside `path`, then a rename), as the command-line tools
    write theirs: vtkPNGWriter does not report a failed write. Raises OSError
    when the file cannot be written.
    """
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    writer = vtkPNGWriter()
    writer.SetInputConnection(grab.GetOutputPort())
    writer.WriteToMemoryOn()
    writer.Write()
    data = bytes(memoryview(writer.GetResult())) if writer.GetResult() else b""
    if not data:
        raise OSError(f"cannot write {path!r}: the window's picture could not be read")
    folder, name = os.path.split(path)
    temporary = os.path.join(folder, f".{name}.partial-{os.getpid()}")
    try:
        with open(temporary, "wb") as out:
            out.write(data)
            out.flush()
            os.fsync(out.fileno())
        os.replace(temporary, path)
    except OSError as error:
        if os.path.exists(temporary):
            os.remove(temporary)
        raise OSError(error.errno, f"cannot write {path!r}: {error.strerror}") from error
    print("wrote", path)
