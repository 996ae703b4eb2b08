"""VTK's own reader (python3-vtk9) over Systole's ParaView series: python3 vtk_check.py SERIES.pvd BAKE ORGAN.

Checks the .pvd lists one data set per frame, each VTU reads with the organ's point count,
carries region, strain, activation and displacement, and holds Systole's positions (its bake)
to float precision at the first, a middle and the last frame."""
import os
import sys
import xml.etree.ElementTree as ET

import vtk
from vtk.util.numpy_support import vtk_to_numpy
import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bake import read_bake  # noqa: E402

series, bake_file, organ = sys.argv[1:4]
fps, bake = read_bake(bake_file)
frames = bake[organ]
datasets = ET.parse(series).getroot().find('Collection').findall('DataSet')
ok = len(datasets) == len(frames)
print('%s: %d data sets in the collection, %d frames simulated' % (series, len(datasets), len(frames)))
worst = 0.0
for f in sorted({0, len(datasets) // 2, len(datasets) - 1}):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(os.path.join(os.path.dirname(series), datasets[f].get('file')))
    reader.Update()
    grid = reader.GetOutput()
    points = vtk_to_numpy(grid.GetPoints().GetData()).astype(float).ravel()
    expected = numpy.array(frames[f])
    arrays = sorted(grid.GetPointData().GetArrayName(i) for i in range(grid.GetPointData().GetNumberOfArrays()))
    same_count = points.size == expected.size
    ok = ok and same_count and arrays == ['activation', 'displacement', 'region', 'strain']
    if same_count:
        worst = max(worst, float(numpy.abs(points - expected).max()))
    print('  frame %d (t = %s s): %d points, %d cells, arrays %s, point 0 at %s'
          % (f, datasets[f].get('timestep'), grid.GetNumberOfPoints(), grid.GetNumberOfCells(), arrays,
             numpy.round(points[:3], 6).tolist()))
ok = ok and worst < 1e-6
print('%s %s: max |VTK - Systole| %.3g m' % ('PASS' if ok else 'FAIL', series, worst))
sys.exit(0 if ok else 1)
