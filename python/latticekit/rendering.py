"""Small rendering helpers shared by the examples."""
import os

from vtkmodules.vtkCommonDataModel import vtkDataObject
from vtkmodules.vtkFiltersExtraction import vtkExtractEdges
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow,
                                         vtkWindowToImageFilter)


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


def save_part_on_bone(bone, part, towards, path, zoom=0.5):
    """Write to the PNG file `path` a printed part (a cutting guide, teal) on
    its bone (ivory), both algorithms, seen from direction `towards` (from
    the part's centre); z up (the head, in LPS and RAS) unless `towards` is
    nearly along z. Off screen, 800 x 600. Raises OSError as save_png."""
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the render window's back end)
    renderer = vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    for source, colour in ((bone, (0.93, 0.87, 0.72)), (part, (0.0, 0.55, 0.6))):
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(source.GetOutputPort())
        mapper.ScalarVisibilityOff()
        actor = vtkActor()
        actor.SetMapper(mapper)
        actor.GetProperty().SetColor(colour)
        renderer.AddActor(actor)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(800, 600)
    window.AddRenderer(renderer)
    length = sum(t * t for t in towards) ** 0.5
    camera = renderer.GetActiveCamera()
    bounds = part.GetOutput().GetBounds()
    centre = [(bounds[2 * k] + bounds[2 * k + 1]) / 2 for k in range(3)]
    camera.SetFocalPoint(centre)
    camera.SetPosition([centre[k] + 200 * towards[k] / length for k in range(3)])
    camera.SetViewUp((0, 0, 1) if abs(towards[2]) < 0.9 * length else (0, 1, 0))
    renderer.ResetCamera(bounds)
    camera.Zoom(zoom)
    save_png(window, path)
