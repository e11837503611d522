"""What ParaView reads from a snapshots.xmf, written out for tests/lib/paraview_compare.py.

Run with pvbatch (no display needed: nothing is rendered):
    pvbatch --force-offscreen-rendering paraview_read.py XMF OUTDIR [XMF OUTDIR ...]

For each XMF (several in one call: ParaView starts once) and each of ParaView's XDMF readers
(XDMFReader, the one the README names, and Xdmf3ReaderS) it loads every time step and writes
OUTDIR/<reader>.json (the time values; per step the point and cell counts and each point
array's name, components and VTK type) and OUTDIR/<reader>_<k>.npz (the points and every
point array of step k). HDF5 is not read here: h5py and ParaView link different HDF5
libraries, so the comparison runs in another process.
"""
import json
import os
import sys

import numpy as np
from paraview import simple
from vtkmodules.util.numpy_support import vtk_to_numpy


def read(xmf, outdir):
    os.makedirs(outdir, exist_ok=True)
    readers = {
        "XDMFReader": lambda: simple.XDMFReader(FileNames=[xmf]),
        "Xdmf3ReaderS": lambda: simple.Xdmf3ReaderS(FileName=[xmf]),
    }
    for name, make in readers.items():
        reader = make()
        reader.UpdatePipelineInformation()
        times = list(reader.TimestepValues)
        steps = []
        for k, t in enumerate(times):
            reader.UpdatePipeline(t)
            data = reader.GetClientSideObject().GetOutputDataObject(0)
            if not data.IsA("vtkPointSet"):
                sys.exit(f"{name}: step {k} is a {data.GetClassName()}, not a point set")
            arrays = {"points": vtk_to_numpy(data.GetPoints().GetData())}
            info = []
            pd = data.GetPointData()
            for i in range(pd.GetNumberOfArrays()):
                a = pd.GetArray(i)
                arrays[a.GetName()] = vtk_to_numpy(a)
                info.append({"name": a.GetName(), "components": a.GetNumberOfComponents(),
                             "type": a.GetDataTypeAsString()})
            np.savez(os.path.join(outdir, f"{name}_{k}.npz"), **arrays)
            steps.append({"points": data.GetNumberOfPoints(), "cells": data.GetNumberOfCells(),
                          "arrays": info})
        with open(os.path.join(outdir, f"{name}.json"), "w") as f:
            json.dump({"times": times, "steps": steps}, f, indent=1)
        simple.Delete(reader)


args = sys.argv[1:]
for i in range(0, len(args) - 1, 2):
    read(os.path.abspath(args[i]), args[i + 1])
