"""Histogram of the full-update times written by BoolSurfRandomSvgBenchmark (paper Fig. 22).

    Testing/run-with-xvfb.sh pvpython Benchmarks/RandomSvg/plot_histogram.py \
        random_svg_booleans.csv random_svg_booleans.png [--cores N]

Bins are equal in log10(time) (the times span two orders of magnitude between 100k and 1M
triangles); bars are stacked by mesh so each mesh's share of the distribution shows. Only
successful trials (status "ok") are counted; the title gives their count, min / median / max
and the core count. Drawn with VTK's charts (vtkChartXY), which pvpython has; rendering needs a
display, hence Xvfb.
"""
import argparse
import csv
import math
import os
import statistics

from vtkmodules.vtkChartsCore import vtkAxis, vtkChart, vtkChartXY, vtkPlotBar
from vtkmodules.vtkCommonColor import vtkColorSeries
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkStringArray
from vtkmodules.vtkCommonDataModel import vtkColor3ub, vtkTable
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
from vtkmodules.vtkViewsContext2D import vtkContextView
import vtkmodules.vtkRenderingContextOpenGL2  # noqa: F401 (the context device)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the render window)
import vtkmodules.vtkRenderingFreeType  # noqa: F401 (text)

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("csv")
parser.add_argument("png")
parser.add_argument("--cores", type=int, default=os.cpu_count())
parser.add_argument("--bins", type=int, default=24)
args = parser.parse_args()

times = {}  # mesh -> [ms]
with open(args.csv, newline="") as f:
    for row in csv.DictReader(f):
        if row["status"] == "ok":
            times.setdefault((int(row["triangles"]), row["mesh"]), []).append(float(row["update_ms"]))
if not times:
    raise SystemExit("no successful trial in " + args.csv)
meshes = sorted(times)
everything = [t for m in meshes for t in times[m]]
lo, hi = math.log10(min(everything)), math.log10(max(everything))
hi = max(hi, lo + 1e-6)
width = (hi - lo) / args.bins

table = vtkTable()
centers = vtkDoubleArray()
centers.SetName("log10 ms")
table.AddColumn(centers)
columns = []
for _, name in meshes:
    column = vtkDoubleArray()
    column.SetName(name)
    table.AddColumn(column)
    columns.append(column)
table.SetNumberOfRows(args.bins)
for b in range(args.bins):
    table.SetValue(b, 0, lo + (b + 0.5) * width)
    for k, mesh in enumerate(meshes):
        count = sum(1 for t in times[mesh]
                    if min(args.bins - 1, int((math.log10(t) - lo) / width)) == b)
        table.SetValue(b, k + 1, count)

view = vtkContextView()
view.GetRenderWindow().SetSize(1000, 560)
view.GetRenderWindow().SetOffScreenRendering(True)
view.GetRenderer().SetBackground(1, 1, 1)
chart = vtkChartXY()
view.GetScene().AddItem(chart)
chart.SetBarWidthFraction(0.95)
chart.SetShowLegend(True)
chart.GetLegend().SetHorizontalAlignment(chart.GetLegend().RIGHT)
chart.GetLegend().SetVerticalAlignment(chart.GetLegend().TOP)
chart.SetTitle("Random SVG Booleans, full update through the VTK filters: %d trials on %d meshes, "
               "min %.1f / median %.1f / max %.1f ms (%d cores)" % (
                   len(everything), len(meshes), min(everything),
                   statistics.median(everything), max(everything), args.cores))
bars = chart.AddPlot(vtkChart.BAR)
bars.SetInputData(table, 0, 1)
for k in range(1, len(meshes)):
    bars.SetInputArray(k + 1, meshes[k][1])
# A qualitative palette, one color per mesh.
palette = [(31, 119, 180), (255, 127, 14), (44, 160, 44), (214, 39, 40), (148, 103, 189),
           (140, 86, 75), (227, 119, 194), (127, 127, 127), (188, 189, 34), (23, 190, 207)]
series = vtkColorSeries()
series.ClearColors()
for rgb in palette[:max(1, len(meshes))]:
    series.AddColor(vtkColor3ub(*rgb))
bars.SetColorSeries(series)
labels = vtkStringArray()
for _, name in meshes:
    labels.InsertNextValue(name)
bars.SetLabels(labels)

x = chart.GetAxis(vtkAxis.BOTTOM)
x.SetTitle("full update (ms), log scale")
ticks = vtkDoubleArray()
tick_labels = vtkStringArray()
for decade in range(math.floor(lo), math.ceil(hi) + 1):
    for m in (1, 2, 5):
        value = math.log10(m) + decade
        if lo - width <= value <= hi + width:
            ticks.InsertNextValue(value)
            tick_labels.InsertNextValue("%g" % (m * 10 ** decade))
x.SetCustomTickPositions(ticks, tick_labels)
x.SetBehavior(vtkAxis.FIXED)
x.SetRange(lo - width, hi + width)
chart.GetAxis(vtkAxis.LEFT).SetTitle("trials")

view.Render()
grab = vtkWindowToImageFilter()
grab.SetInput(view.GetRenderWindow())
grab.Update()
writer = vtkPNGWriter()
writer.SetFileName(args.png)
writer.SetInputConnection(grab.GetOutputPort())
writer.Write()
print("wrote %s: %d trials, median %.1f ms" % (args.png, len(everything),
                                                statistics.median(everything)))
