#!/usr/bin/env python3
"""Gallery: a result opened from its XDMF sidecar the way ParaView opens it
(VTK's vtkXdmfReader) and drawn offscreen to a PNG (docs/gallery.md#opening-a-result-in-paraview).

  paraview_screenshot.py STRESS.xdmf --out PNG

STRESS.xdmf is the sidecar of a stress file (examples/gallery/von_mises.sh
makes hertz_stress.xdmf): the surface pressure on the back half of the
surface, and the von Mises stress on the x-z plane through the centre of
the volume below it. Needs the
vtk wheel (pip install vtk), whose renderer works without a display.
"""

import argparse

from vtkmodules.vtkCommonDataModel import vtkPlane
from vtkmodules.vtkFiltersCore import vtkCutter
from vtkmodules.vtkFiltersGeneral import vtkClipDataSet
from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter
from vtkmodules.vtkFiltersModeling import vtkOutlineFilter
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOXdmf2 import vtkXdmfReader
from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor
from vtkmodules.vtkRenderingCore import (vtkActor, vtkDataSetMapper, vtkRenderer, vtkRenderWindow,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the renderer's implementation)


def blocks(path):
    reader = vtkXdmfReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutputDataObject(0)
    return {data.GetMetaData(k).Get(data.NAME()): data.GetBlock(k) for k in range(data.GetNumberOfBlocks())}


def actor(data, array, cells, bar_title=None, renderer=None):
    mapper = vtkDataSetMapper()
    mapper.SetInputData(data)
    if cells:
        mapper.SetScalarModeToUseCellFieldData()
    else:
        mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray(array)
    values = (data.GetCellData() if cells else data.GetPointData()).GetArray(array)
    mapper.SetScalarRange(values.GetRange())
    lut = mapper.GetLookupTable()
    lut.SetHueRange(0.667, 0.0)
    result = vtkActor()
    result.SetMapper(mapper)
    if bar_title and renderer:
        bar = vtkScalarBarActor()
        bar.SetLookupTable(lut)
        bar.SetTitle(bar_title)
        bar.SetNumberOfLabels(3)
        bar.SetWidth(0.08)
        bar.SetHeight(0.4)
        bar.GetTitleTextProperty().SetColor(0, 0, 0)
        bar.GetLabelTextProperty().SetColor(0, 0, 0)
        renderer.AddViewProp(bar)
        return result, bar
    return result, None


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("xdmf")
    parser.add_argument("--out", required=True)
    args = parser.parse_args()
    grids = blocks(args.xdmf)
    surface, volume = grids["surface"], grids["stress"]

    renderer = vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    # The von Mises stress on the plane y = centre, cut from the volume.
    plane = vtkPlane()
    plane.SetOrigin(volume.GetCenter())
    plane.SetNormal(0, 1, 0)
    cut = vtkCutter()
    cut.SetInputData(volume)
    cut.SetCutFunction(plane)
    cut.Update()
    section, bar = actor(cut.GetOutput(), "von_mises", cells=False, bar_title="von Mises (Pa)", renderer=renderer)
    bar.SetPosition(0.88, 0.1)
    renderer.AddActor(section)
    # The surface layer coloured by the pressure, its front half clipped
    # away (as ParaView's Clip does) to uncover the section; the volume's outline.
    clip = vtkClipDataSet()
    clip.SetInputData(surface)
    clip.SetClipFunction(plane)
    clip.Update()
    top = vtkDataSetSurfaceFilter()
    top.SetInputData(clip.GetOutput())
    top.Update()
    pressure, pressure_bar = actor(top.GetOutput(), "pressure", cells=True, bar_title="pressure (Pa)",
                                   renderer=renderer)
    pressure_bar.SetPosition(0.02, 0.1)
    renderer.AddActor(pressure)
    outline = vtkOutlineFilter()
    outline.SetInputData(volume)
    outline.Update()
    box = vtkActor()
    box_mapper = vtkDataSetMapper()
    box_mapper.SetInputData(outline.GetOutput())
    box.SetMapper(box_mapper)
    box.GetProperty().SetColor(0.3, 0.3, 0.3)
    renderer.AddActor(box)

    camera = renderer.GetActiveCamera()
    camera.SetViewUp(0, 0, 1)
    camera.SetPosition(0.6, -1.6, 0.9)
    camera.SetFocalPoint(0, 0, 0)
    renderer.ResetCamera()
    camera.Zoom(1.3)

    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(640, 420)
    window.Render()
    image = vtkWindowToImageFilter()
    image.SetInput(window)
    image.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(args.out)
    writer.SetInputConnection(image.GetOutputPort())
    writer.Write()
    print(args.out)


if __name__ == "__main__":
    main()
